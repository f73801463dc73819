#!/usr/bin/env bash
# whitted-mpi against whitted: the same bytes for any ranks, threads, tile size and schedule, and
# the job's behaviour on Ctrl-C, a killed rank (then --resume), a bad scene and mismatched ranks.
# Usage: mpi_test.sh CASE   with WHITTED, WHITTED_MPI and SOURCE_DIR set (tests/CMakeLists.txt).
set -uo pipefail
MODES="whitted raycast normals depth path"  # every render mode; a new mode is one word here

case_name=$1
src=$SOURCE_DIR
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
MPIRUN=(mpirun --oversubscribe --allow-run-as-root --mca btl self,vader)
# Under the sanitizer build: Open MPI's own allocations (its components, MPI_Init's state) are still
# held at exit, which LeakSanitizer reports as leaks of ours. Leaks of whitted's own code are checked
# by every other test; here the address and undefined-behaviour checks stay on, the leak check off.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
SIZE=(--width 96 --height 72)
fail() { echo "FAIL: $*"; exit 1; }

# Renders SCENE with whitted to $out/ref.png (extra args after SCENE).
reference() { "$WHITTED" "$1" -o "$out/ref.png" -q "${SIZE[@]}" "${@:2}" || fail "whitted $*"; }
# Renders with N ranks to $out/mpi.png and compares it with ref.png byte for byte.
same_as_reference() {
    local n=$1
    shift
    "${MPIRUN[@]}" -np "$n" "$WHITTED_MPI" "$@" -o "$out/mpi.png" -q "${SIZE[@]}" >"$out/log" 2>&1 ||
        { cat "$out/log"; fail "mpirun -np $n whitted-mpi $*"; }
    cmp "$out/ref.png" "$out/mpi.png" || fail "-np $n whitted-mpi $* differs from whitted"
    echo "ok: -np $n $*"
}
# 1-4 ranks, each with other threads, tile size and schedule order.
all_rank_counts() {
    local scene=$1
    shift
    reference "$scene" "$@"
    same_as_reference 1 "$scene" "$@" --threads 2 --tile-size 16
    same_as_reference 2 "$scene" "$@" --threads 1 --tile-size 32 --test-schedule-seed 2
    same_as_reference 3 "$scene" "$@" --threads 2 --tile-size 7 --test-schedule-seed 3
    same_as_reference 4 "$scene" "$@" --threads 1 --tile-size 64
}
# Starts a slowed 3-rank job (100 ms a tile: about 4 s) in the background, $job its mpirun's pid,
# and returns once some tiles are in its checkpoint $out/ck.
start_slow_job() {
    "${MPIRUN[@]}" -np 3 "$WHITTED_MPI" "$src/scenes/textures.sc" -o "$out/mpi.png" "${SIZE[@]}" --threads 1 \
        --tile-size 8 --test-slow-ms 100 --checkpoint "$out/ck" --checkpoint-every 0.1 "$@" >"$out/log" 2>&1 &
    job=$!
    for _ in $(seq 300); do
        (($(stat -c %s "$out/ck" 2>/dev/null || echo 0) > 5000)) && return
        sleep 0.1
    done
    fail "no tile finished in 30 s"
}
tmp_files_left() { ls -A "$out" | grep -q '\.tmp'; }  # of the image or the checkpoint

case $case_name in
whitted_scene) all_rank_counts "$src/scenes/showcase.sc" ;;
textured_scene) all_rank_counts "$src/scenes/textures.sc" --aa 2 ;;
spp16_scene) all_rank_counts "$src/tests/mpi/effects.sc" --spp 16 ;;
path_scene) all_rank_counts "$src/scenes/features/cornell_box.sc" --mode path --spp 8 --max-depth 8 ;;
mesh_scene)
    # Triangle meshes (§9.3) go through the same load path on every rank: Whitted, then path mode.
    all_rank_counts "$src/scenes/features/mesh.sc"
    reference "$src/scenes/features/mesh.sc" --mode path --spp 4 --max-depth 4
    same_as_reference 3 "$src/scenes/features/mesh.sc" --mode path --spp 4 --max-depth 4 --tile-size 16 \
        --test-schedule-seed 4 ;;
adaptive_aa) reference "$src/scenes/showcase.sc" --aa 3 --aa-threshold 0.1
    same_as_reference 3 "$src/scenes/showcase.sc" --aa 3 --aa-threshold 0.1 --tile-size 8 --test-schedule-seed 5 ;;
modes)
    for mode in $MODES; do
        reference "$src/tests/mpi/effects.sc" --mode "$mode" --spp 4
        same_as_reference 3 "$src/tests/mpi/effects.sc" --mode "$mode" --spp 4 --tile-size 16 --test-schedule-seed 9
    done ;;
slow_rank)
    # Rank 1 takes 60 ms a tile: the others take over its share at the tail, duplicates compared.
    # They take 4 ms (about 0.15 s in all), so that rank 1 has its share even if it starts late.
    reference "$src/scenes/textures.sc"
    same_as_reference 3 "$src/scenes/textures.sc" --tile-size 8 --test-slow-rank 1 --test-slow-ms 60 \
        --test-slow-others-ms 4 --stats
    grep -Eq "[1-9][0-9]* duplicates sent" "$out/log" || { cat "$out/log"; fail "no tile was handed out twice"; } ;;
verify)
    # --verify: every tile on two ranks, compared; the same bytes. One rank cannot verify.
    reference "$src/scenes/textures.sc"
    same_as_reference 3 "$src/scenes/textures.sc" --tile-size 8 --threads 1 --verify --stats --test-schedule-seed 6
    grep -q "108 rendered twice and compared" "$out/log" || { cat "$out/log"; fail "not every tile was compared"; }
    "$WHITTED_MPI" "$src/scenes/textures.sc" -o "$out/one.png" --verify >"$out/log" 2>&1 && fail "one rank verified"
    grep -q "needs at least two ranks" "$out/log" || { cat "$out/log"; fail "no message"; }
    [[ ! -e $out/one.png ]] || fail "one rank wrote an image" ;;
stats)
    # --stats: every rank times its traversals, and rank 0 prints all ranks' rays and rates of each
    # kind (the showcase traces all four), as whitted prints its own; the pixels are the same.
    reference "$src/scenes/showcase.sc"
    same_as_reference 2 "$src/scenes/showcase.sc" --threads 1 --tile-size 16 --stats
    r='([1-9][0-9]*\.[0-9]+|0\.[0-9]*[1-9][0-9]*)'  # a rate above zero
    grep -Eq "^traversal Mrays/s per thread \(1 in 32 timed\): camera $r, reflected $r, refracted $r, shadow $r$" \
        "$out/log" || { cat "$out/log"; fail "no rate for each kind of ray"; }
    camera=$(sed -n 's/^rays: camera \([0-9]*\), reflected [1-9][0-9]*, refracted [1-9][0-9]*, shadow [1-9][0-9]*;.*/\1/p' "$out/log")
    ((${camera:-0} >= 96 * 72)) || { cat "$out/log"; fail "not every ray counted: camera ${camera:-none}"; } ;;
duplicate_mismatch)
    # Rank 1's pixels are off by a little; with --verify each of its tiles is compared with rank 0's
    # (whichever comes first), so the job is refused whatever the timing. (Tail duplicates go through
    # the same comparison but only when the second copy beats the end of the job: not a test.)
    "${MPIRUN[@]}" -np 2 "$WHITTED_MPI" "$src/scenes/textures.sc" -o "$out/mpi.png" "${SIZE[@]}" --tile-size 8 \
        --threads 1 --verify --test-corrupt-rank 1 >"$out/log" 2>&1
    rc=$?
    [[ $rc == 4 ]] || { cat "$out/log"; fail "exit code $rc, not 4"; }
    grep -q "to other bytes than the rank that rendered it first" "$out/log" || fail "no mismatch message"
    [[ ! -e $out/mpi.png ]] || fail "an image was written from disagreeing ranks" ;;
ctrl_c)
    # Ctrl-C on mpirun: SIGTERM to every rank; rank 0 writes the partial image atomically, beside
    # the output (a good image already there is never replaced by a partial one).
    printf 'good image' >"$out/mpi.png"
    start_slow_job
    kill -INT "$job"
    wait "$job"
    cat "$out/log"
    grep -q "interrupted: wrote the [0-9]* of 108 tiles of the first pass to $out/mpi.partial.png" "$out/log" ||
        fail "no partial write"
    head -c 8 "$out/mpi.partial.png" | od -An -c | grep -q "P   N   G" || fail "the partial image is not a PNG"
    [[ "$(cat "$out/mpi.png")" == "good image" ]] || fail "the existing output was replaced"
    tmp_files_left && fail "temporary files left: $(ls "$out")"
    echo "ok" ;;
sigterm_exit_code)
    # SIGTERM to every rank (what mpirun and Slurm do): every rank exits 130.
    start_slow_job
    kill -TERM $(pgrep -P "$job")
    wait "$job"
    rc=$?
    [[ $rc == 130 ]] || { cat "$out/log"; fail "exit code $rc, not 130"; }
    grep -q "interrupted: wrote the" "$out/log" || fail "no partial write" ;;
killed_rank_resume)
    # A rank killed part-way aborts the job; --resume renders only the missing tiles, same bytes.
    reference "$src/scenes/textures.sc"
    start_slow_job
    kill -KILL $(pgrep -P "$job" | tail -1)
    wait "$job"
    # mpirun sends SIGTERM to the ranks left: rank 0 may write the part it has, a whole PNG, beside the output.
    [[ ! -e $out/mpi.png ]] || fail "a partial image was written over the output"
    [[ ! -e $out/mpi.partial.png ]] || head -c 8 "$out/mpi.partial.png" | od -An -c | grep -q "P   N   G" ||
        fail "not a PNG"
    tmp_files_left && fail "temporary files left: $(ls "$out")"
    [[ -s $out/ck ]] || { cat "$out/log"; fail "no checkpoint"; }
    same_as_reference 2 "$src/scenes/textures.sc" --threads 1 --tile-size 8 --resume "$out/ck" --checkpoint "$out/ck"
    "${MPIRUN[@]}" -np 2 "$WHITTED_MPI" "$src/scenes/textures.sc" -o "$out/mpi.png" "${SIZE[@]}" --tile-size 8 \
        --resume "$out/ck" >"$out/log" 2>&1 || fail "second resume"
    grep -Eq "resuming from $out/ck: 1 of 1 whole passes" "$out/log" ||
        { cat "$out/log"; fail "the resumed run's checkpoint does not hold every tile"; }
    cmp "$out/ref.png" "$out/mpi.png" || fail "resumed twice: differs"
    # A checkpoint of another job is refused.
    "${MPIRUN[@]}" -np 2 "$WHITTED_MPI" "$src/scenes/textures.sc" -o "$out/other.png" --width 97 --height 72 \
        --tile-size 8 --resume "$out/ck" >"$out/log" 2>&1 && fail "a checkpoint of another image size was used"
    grep -q "resume with the options it was made with" "$out/log" || { cat "$out/log"; fail "no message"; }
    # And one made at another scene time (a frame of the animation): every setting that changes
    # pixels is in the key, --time too, so the resume would mix two frames.
    "${MPIRUN[@]}" -np 2 "$WHITTED_MPI" "$src/scenes/textures.sc" -o "$out/other.png" "${SIZE[@]}" --tile-size 8 \
        --time 0.5 --resume "$out/ck" >"$out/log" 2>&1 && fail "a checkpoint of another --time was used"
    grep -q "was made with --time 0, not 0.5" "$out/log" || { cat "$out/log"; fail "no message"; }
    # The file format and key are whitted's (at whitted's tile size, 32): each goes on from the other's file.
    "${MPIRUN[@]}" -np 2 "$WHITTED_MPI" "$src/scenes/textures.sc" -o "$out/mpi.png" "${SIZE[@]}" -q \
        --checkpoint "$out/ck32" >"$out/log" 2>&1 || { cat "$out/log"; fail "whitted-mpi --checkpoint"; }
    "$WHITTED" "$src/scenes/textures.sc" -o "$out/w.png" "${SIZE[@]}" --resume "$out/ck32" >"$out/log" 2>&1 ||
        { cat "$out/log"; fail "whitted --resume of whitted-mpi's checkpoint"; }
    grep -q "resuming from $out/ck32: 1 of 1 whole passes" "$out/log" || { cat "$out/log"; fail "whitted resumed nothing"; }
    cmp "$out/ref.png" "$out/w.png" || fail "whitted resumed whitted-mpi's checkpoint: differs"
    "$WHITTED" "$src/scenes/textures.sc" -o "$out/w2.png" "${SIZE[@]}" --threads 1 --checkpoint "$out/ckw" \
        --test-interrupt-after-tiles 3 >"$out/log" 2>&1
    [[ $? == 130 ]] || { cat "$out/log"; fail "whitted --test-interrupt-after-tiles"; }
    "${MPIRUN[@]}" -np 2 "$WHITTED_MPI" "$src/scenes/textures.sc" -o "$out/mpi.png" "${SIZE[@]}" \
        --resume "$out/ckw" >"$out/log" 2>&1 || { cat "$out/log"; fail "whitted-mpi --resume of whitted's checkpoint"; }
    grep -q "resuming from $out/ckw: 3 of 9 tiles of the first pass" "$out/log" || { cat "$out/log"; fail "whitted-mpi resumed nothing"; }
    cmp "$out/ref.png" "$out/mpi.png" || fail "whitted-mpi resumed whitted's checkpoint: differs" ;;
scene_error)
    # One error (a colour with two numbers), so that one message per rank would be seen as three.
    printf 'camera [ eye 0 0 5 ]\nmastersubgraph root [ trans [\n  object sphere [ diffuse 1 1 ]\n] ]\n' >"$out/bad.sc"
    "${MPIRUN[@]}" -np 3 "$WHITTED_MPI" "$out/bad.sc" -o "$out/mpi.png" >"$out/log" 2>&1
    rc=$?
    cat "$out/log"
    [[ $rc == 2 ]] || fail "exit code $rc, not 2"
    [[ $(grep -c "bad.sc:3:[0-9]*: error" "$out/log") == 1 ]] || fail "the error is not reported exactly once"
    [[ ! -e $out/mpi.png ]] || fail "an image was written" ;;
hostile_input)
    # On rank 0: /dev/zero is refused at once (it never ends), and a missing output folder
    # before anything is loaded; every rank exits 3 and nothing is written.
    timeout 60 "${MPIRUN[@]}" -np 2 "$WHITTED_MPI" /dev/zero -o "$out/mpi.png" >"$out/log" 2>&1
    rc=$?
    cat "$out/log"
    [[ $rc == 3 ]] || fail "/dev/zero: exit code $rc, not 3"
    grep -q "it is not a regular file" "$out/log" || fail "/dev/zero: no message"
    timeout 60 "${MPIRUN[@]}" -np 2 "$WHITTED_MPI" "$src/scenes/textures.sc" -o "$out/no/such/dir/mpi.png" \
        >"$out/log" 2>&1
    rc=$?
    cat "$out/log"
    [[ $rc == 3 ]] || fail "missing folder: exit code $rc, not 3"
    grep -q "the folder '$out/no/such/dir' does not exist" "$out/log" || fail "missing folder: no message"
    [[ ! -e $out/mpi.png ]] || fail "an image was written" ;;
mismatched_ranks)
    "${MPIRUN[@]}" -np 1 "$WHITTED_MPI" "$src/scenes/textures.sc" -o "$out/a.png" : \
        -np 1 "$WHITTED_MPI" "$src/scenes/textures.sc" -o "$out/a.png" --width 100 >"$out/log" 2>&1 && fail "accepted"
    grep -q "rank 1 was started with other options than rank 0" "$out/log" || { cat "$out/log"; fail "no message"; }
    cp "$WHITTED_MPI" "$out/other-build" && printf 'x' >>"$out/other-build"
    "${MPIRUN[@]}" -np 1 "$WHITTED_MPI" "$src/scenes/textures.sc" -o "$out/a.png" : \
        -np 1 "$out/other-build" "$src/scenes/textures.sc" -o "$out/a.png" >"$out/log" 2>&1 && fail "accepted"
    grep -q "rank 1 runs another whitted-mpi executable" "$out/log" || { cat "$out/log"; fail "no message"; } ;;
narrow_terminal)
    # on a terminal narrower than the progress line each update wrapped into a
    # new line. Run alone (one rank, no mpirun, whose ranks write into pipes) in a terminal of
    # 30, 42 and 12 columns, every redraw leaves the last column free and still shows the percentage.
    for cols in 30 42 12; do
        script -qfec "stty cols $cols rows 24; exec $(printf '%q ' "$WHITTED_MPI" "$src/scenes/showcase.sc" \
            -o "$out/mpi.png" --width 300 --height 300 --spp 4 --threads 2)" /dev/null >"$out/log" 2>&1 ||
            { cat -A "$out/log"; fail "$cols columns: whitted-mpi failed"; }
        # Each draw starts with carriage return and erase-line, and ends at the next carriage return.
        tr '\r' '\n' <"$out/log" | sed -n $'s/^\033\\[K//p' | grep -v '^wrote \|^$' >"$out/draws"
        [[ -s $out/draws ]] || { cat -A "$out/log"; fail "$cols columns: no progress line drawn"; }
        awk -v cols="$cols" 'length($0) >= cols || !/%/ { print "too wide or no percentage: \"" $0 "\""; bad = 1 }
            END { exit bad }' "$out/draws" || fail "$cols columns: a line does not fit"
        echo "ok: $cols columns, $(wc -l <"$out/draws") draws"
    done ;;
checkpoint_conflict)
    # --checkpoint scene.sc overwrote the scene (exit 0), and --checkpoint good.png
    # -o good.png + Ctrl-C the image. A checkpoint that is anything the job reads or writes is refused
    # before a byte is written; --resume reads only a regular file.
    cp -r "$src/scenes/textures.sc" "$src/scenes/textures" "$out/"
    cp "$out/textures.sc" "$out/scene-before.sc"
    printf 'good image' >"$out/good.png"
    ln -s textures.sc "$out/link.sc"
    for ck in "$out/textures.sc" "$out/link.sc" "$out/good.png" "$out/good.partial.png" "$out/textures/world.png"; do
        "${MPIRUN[@]}" -np 2 "$WHITTED_MPI" "$out/textures.sc" -o "$out/good.png" "${SIZE[@]}" --checkpoint "$ck" \
            >"$out/log" 2>&1
        rc=$?
        [[ $rc == 1 ]] || { cat "$out/log"; fail "--checkpoint $ck: exit code $rc, not 1"; }
        grep -q "error: --checkpoint '$ck' is" "$out/log" || { cat "$out/log"; fail "--checkpoint $ck: no message"; }
    done
    cmp "$out/textures.sc" "$out/scene-before.sc" || fail "the scene was changed"
    [[ "$(cat "$out/good.png")" == "good image" ]] || fail "the image was changed"
    [[ ! -e $out/good.partial.png ]] || fail "a partial image was written"
    mkfifo "$out/fifo"
    for ck in /dev/zero "$out/fifo"; do
        timeout 60 "${MPIRUN[@]}" -np 2 "$WHITTED_MPI" "$out/textures.sc" -o "$out/new.png" "${SIZE[@]}" \
            --resume "$ck" >"$out/log" 2>&1
        rc=$?
        [[ $rc == 1 ]] || { cat "$out/log"; fail "--resume $ck: exit code $rc, not 1"; }
        grep -q "cannot read the checkpoint '$ck': it is not a regular file" "$out/log" ||
            { cat "$out/log"; fail "--resume $ck: no message"; }
    done
    echo "ok" ;;
mesh_resume)
    # the mesh bytes are broadcast with the scene and counted in the job's key: a
    # checkpoint made before a mesh file changed is refused (it gave half old blob, half new, exit 0).
    mkdir -p "$out/features" && cp "$src/scenes/features/mesh.sc" "$out/features/" && cp -r "$src/scenes/meshes" \
        "$src/scenes/textures" "$out/"
    "${MPIRUN[@]}" -np 2 "$WHITTED_MPI" "$out/features/mesh.sc" -o "$out/a.png" "${SIZE[@]}" --tile-size 16 \
        --checkpoint "$out/ck" >"$out/log" 2>&1 || { cat "$out/log"; fail "first run"; }
    sed -i 's/^v \([-0-9.e]*\) /v 0.5 /' "$out/meshes/blob.obj"  # another mesh
    "${MPIRUN[@]}" -np 2 "$WHITTED_MPI" "$out/features/mesh.sc" -o "$out/b.png" "${SIZE[@]}" --tile-size 16 \
        --resume "$out/ck" >"$out/log" 2>&1 && { cat "$out/log"; fail "a checkpoint of the old mesh was used"; }
    grep -q "was made from another scene, textures or meshes" "$out/log" ||
        { cat "$out/log"; fail "no message"; }
    echo "ok" ;;
timeout)
    # --timeout (60 s by default under --untrusted, which had none): the job stops as on Ctrl-C, writes
    # the part rendered beside the output, exits 130 saying why.
    "${MPIRUN[@]}" -np 2 "$WHITTED_MPI" "$src/scenes/textures.sc" -o "$out/mpi.png" "${SIZE[@]}" --threads 1 \
        --tile-size 8 --test-slow-ms 100 --untrusted --timeout 1.5 >"$out/log" 2>&1
    rc=$?
    cat "$out/log"
    [[ $rc == 130 ]] || fail "exit code $rc, not 130"
    grep -q "the time limit of 1.5 s (--timeout) ran out: wrote the [0-9]* of 108 tiles" "$out/log" ||
        fail "no message"
    [[ -e $out/mpi.partial.png && ! -e $out/mpi.png ]] || fail "not written beside the output" ;;
noise_threshold)
    # Adaptive sampling: rank 0's session decides which pixels stop between passes; the pixels still
    # sampling travel with each tile. The same bytes as whitted's.
    reference "$src/scenes/features/soft_shadows.sc" --spp 32 --noise-threshold 0.05
    same_as_reference 3 "$src/scenes/features/soft_shadows.sc" --spp 32 --noise-threshold 0.05 --tile-size 16 \
        --test-schedule-seed 7 ;;
time_limit)
    # Whole passes while they fit, then the complete image (exit 0) of the samples reached: the
    # pixels of a render of that many samples. The budget counts mpirun's start and the load, which
    # take most of 2 s under the sanitizers: 5 s leaves room for passes.
    "${MPIRUN[@]}" -np 2 "$WHITTED_MPI" "$src/scenes/features/soft_shadows.sc" -o "$out/mpi.png" --width 64 \
        --height 48 --spp 65536 --time-limit 5 --threads 1 --tile-size 16 >"$out/log" 2>&1 ||
        { cat "$out/log"; fail "exit code $?"; }
    grep -q "fitted in the time limit of 5 s (65536 asked for)" "$out/log" || { cat "$out/log"; fail "no message"; }
    samples=$(sed -n 's/.*: the \([0-9]*\) samples per pixel of \([0-9]*\) whole passes fitted.*/\1/p' "$out/log")
    [[ -n $samples && $samples -ge 2 ]] || { cat "$out/log"; fail "fewer than two passes in 5 s"; }
    [[ ! -e $out/mpi.partial.png ]] || fail "a partial image was written"
    "$WHITTED" "$src/scenes/features/soft_shadows.sc" -o "$out/ref.png" --width 64 --height 48 --spp "$samples" -q ||
        fail "whitted --spp $samples"
    "$WHITTED" compare "$out/ref.png" "$out/mpi.png" >"$out/cmp" 2>&1
    grep -q "the images are equal" "$out/cmp" || { cat "$out/cmp"; fail "not the pixels of --spp $samples"; }
    echo "ok: $samples samples" ;;
later_pass_interrupt)
    # Ctrl-C in the third pass (tiles 1-24 are the first two of 12 tiles each): the partial image is the
    # last whole pass (2 samples per pixel), not a mix of passes.
    "${MPIRUN[@]}" -np 2 "$WHITTED_MPI" "$src/scenes/features/soft_shadows.sc" -o "$out/mpi.png" --width 64 \
        --height 48 --spp 16 --tile-size 16 --threads 1 --test-interrupt-after-tiles 27 >"$out/log" 2>&1
    rc=$?
    [[ $rc == 130 ]] || { cat "$out/log"; fail "exit code $rc, not 130"; }
    grep -q "interrupted: wrote the 2 samples per pixel of 2 whole passes to $out/mpi.partial.png" "$out/log" ||
        { cat "$out/log"; fail "not the last whole pass"; }
    [[ ! -e $out/mpi.png ]] || fail "the output was written"
    "$WHITTED" "$src/scenes/features/soft_shadows.sc" -o "$out/ref.png" --width 64 --height 48 --spp 2 -q ||
        fail "whitted --spp 2"
    "$WHITTED" compare "$out/ref.png" "$out/mpi.partial.png" >"$out/cmp" 2>&1
    grep -q "the images are equal" "$out/cmp" || { cat "$out/cmp"; fail "not the pixels of --spp 2"; }
    echo "ok" ;;
frames)
    # --frames across the ranks: each frame whitted's bytes (a moving scene, read again at each frame's
    # time); a frame whose file exists is left alone; Ctrl-C inside a frame writes no part of it, and
    # the same command run again finishes the sequence.
    "$WHITTED" "$src/tests/mpi/moving.sc" -o "$out/ref.png" --frames 0..3 --fps 2 "${SIZE[@]}" -q ||
        fail "whitted --frames"
    cmp -s "$out/ref.0000.png" "$out/ref.0003.png" && fail "the scene does not move"
    echo "a frame of an earlier run" >"$out/mpi.0001.png"
    "${MPIRUN[@]}" -np 3 "$WHITTED_MPI" "$src/tests/mpi/moving.sc" -o "$out/mpi.png" --frames 0..3 --fps 2 \
        "${SIZE[@]}" --threads 1 --tile-size 16 --test-schedule-seed 3 >"$out/log" 2>&1 ||
        { cat "$out/log"; fail "whitted-mpi --frames"; }
    grep -q "frame 1: $out/mpi.0001.png exists, skipped" "$out/log" || { cat "$out/log"; fail "no skip"; }
    [[ $(cat "$out/mpi.0001.png") == "a frame of an earlier run" ]] || fail "an existing frame was replaced"
    for n in 0000 0002 0003; do
        cmp "$out/ref.$n.png" "$out/mpi.$n.png" || fail "frame $n differs from whitted's"
    done
    rm "$out"/mpi.*
    "${MPIRUN[@]}" -np 2 "$WHITTED_MPI" "$src/tests/mpi/moving.sc" -o "$out/mpi.png" --frames 0..3 --fps 2 \
        "${SIZE[@]}" --threads 1 --tile-size 16 --test-interrupt-after-tiles 5 >"$out/log" 2>&1
    rc=$?
    [[ $rc == 130 ]] || { cat "$out/log"; fail "exit code $rc, not 130"; }
    grep -q "interrupted in frame 0: $out/mpi.0000.png not written" "$out/log" || { cat "$out/log"; fail "no message"; }
    ls "$out" | grep -q '^mpi\.' && { ls "$out"; fail "something was written"; }
    "${MPIRUN[@]}" -np 2 "$WHITTED_MPI" "$src/tests/mpi/moving.sc" -o "$out/mpi.png" --frames 0..3 --fps 2 \
        "${SIZE[@]}" --threads 1 --tile-size 16 >"$out/log" 2>&1 || { cat "$out/log"; fail "the run again"; }
    for n in 0000 0001 0002 0003; do
        cmp "$out/ref.$n.png" "$out/mpi.$n.png" || fail "frame $n differs from whitted's after the run again"
    done
    echo "ok" ;;
shutter)
    # Motion blur: every rank builds the moving instances' own BVH over the shutter and each sample's
    # time comes from the sampler, so the tiles are whitted's whatever rank renders them.
    reference "$src/tests/mpi/moving.sc" --shutter 0,0.5 --spp 8
    "$WHITTED" "$src/tests/mpi/moving.sc" -o "$out/still.png" -q "${SIZE[@]}" --spp 8 || fail "whitted still"
    cmp -s "$out/ref.png" "$out/still.png" && fail "the shutter blurred nothing"
    same_as_reference 3 "$src/tests/mpi/moving.sc" --shutter 0,0.5 --spp 8 --tile-size 16 --threads 1 \
        --test-schedule-seed 6 ;;
*) fail "unknown case $case_name" ;;
esac

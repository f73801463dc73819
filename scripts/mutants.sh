#!/usr/bin/env bash
# Planted bugs ("mutants"): each is a one-line change to one source file, made in a scratch copy
# of the tree, built (Release, -j2) and tested with the tests meant to catch it (a gtest filter
# of the one test binary); then the line is put back. A mutant whose tests still pass SURVIVED:
# some behaviour is unguarded. The goal is no survivor. Slow (a build per mutant), so not in CI:
# run it before resolving an issue and record the result in docs/testing.md.
#
# Usage: scripts/mutants.sh [--check] [NAME...]
#   NAME...   only these mutants (default: all)
#   --check   only check that every mutant's line is still found exactly once (no build)
# Environment: WHITTED_MUTANTS_DIR (scratch, default /tmp/whitted-mutants), WHITTED_MUTANTS_JOBS
# (build jobs, default 2), WHITTED_SHARED_DIR (the shared corpus, default <source>/../shared).
#
# A mutant names its line by its exact text (leading blanks ignored), not by a line number, so
# that edits elsewhere in the file do not move it. If the line is changed on purpose, the mutant
# must be updated (the run reports it as STALE and fails).
set -uo pipefail
{  # read whole before it runs: editing this file during a run then cannot derail the run
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
scratch="${WHITTED_MUTANTS_DIR:-/tmp/whitted-mutants}"
jobs="${WHITTED_MUTANTS_JOBS:-2}"
src="$scratch/src"
build="$scratch/build"

names=() files=() finds=() plants=() filters=()
# mutant NAME FILE 'LINE AS IT IS' 'LINE PLANTED' 'GTEST FILTER'
mutant() { names+=("$1"); files+=("$2"); finds+=("$3"); plants+=("$4"); filters+=("$5"); }

# --- The survivors of the test audit and the bugs its new tests were written for.
mutant sah-ignores-left-count src/accel/bvh_build.cpp \
    'const float cost = acc.area() * float(acc_n) + right_cost[i + 1];' \
    'const float cost = acc.area() + right_cost[i + 1];' \
    'Bvh*'
mutant sah-never-makes-a-leaf src/accel/bvh_build.cpp \
    'if (best_split < 0 || (split_cost >= leaf_cost && count <= kMaxLeaf)) {' \
    'if (best_split < 0) {' \
    'Bvh*'
mutant adaptive-aa-ignores-up-and-down src/render/tile_renderer.cpp \
    'return far(x - 1, y) || far(x + 1, y) || far(x, y - 1) || far(x, y + 1);' \
    'return far(x - 1, y) || far(x + 1, y);' \
    'Renderer.*:AdaptiveAntiAliasing.*'
mutant normals-view-flipped src/integrator/debug_views.cpp \
    'return 0.5f * (surface_at(scene_, ray, hit).normal + 1.0f);' \
    'return 0.5f * (1.0f - surface_at(scene_, ray, hit).normal);' \
    'WhittedIntegrator.*:DebugViews.*:Renderer.*'
mutant depth-view-inverted src/integrator/debug_views.cpp \
    'return glm::vec3(1.0f - std::clamp((d - near_) / (far_ - near_), 0.0f, 1.0f));' \
    'return glm::vec3(std::clamp((d - near_) / (far_ - near_), 0.0f, 1.0f));' \
    'WhittedIntegrator.*:DebugViews.*:Renderer.*'
mutant second-ctrl-c-ignored apps/common/interrupt.cpp \
    'if (g_interrupted.exchange(true)) {' \
    'if (g_interrupted.exchange(true) && false) {' \
    'Cli*Interrupt*'
mutant controller-destructor-waits-for-the-render apps/viewer/render_controller.cpp \
    'for (auto& j : jobs_) j->cancel = true;' \
    'for (auto& j : jobs_) (void)j;' \
    'RenderController.*'
mutant cylinder-top-cap-v-flipped src/shapes/unit_shapes.cpp \
    'case kPartTopCap: case kPartPosY: u = p.x + 0.5f; v = p.z + 0.5f; break;' \
    'case kPartTopCap: u = p.x + 0.5f; v = 0.5f - p.z; break; case kPartPosY: u = p.x + 0.5f; v = p.z + 0.5f; break;' \
    'SceneImages.*'
mutant error-at-the-end-has-no-line src/parse/lexer.cpp \
    'end.line = end_line;' \
    'end.line = 0;' \
    'ParseRobustness.*'

# --- Bugs the audit planted in the well-guarded core (lighting, refraction, glass shadows,
# texture coordinates, the BVH partition, tiling), kept so that it stays guarded.
mutant specular-mirror-direction-halved src/integrator/whitted_integrator.cpp \
    'glm::vec3 r = 2.0f * n_dot_l * n - ls.to_light;' \
    'glm::vec3 r = n_dot_l * n - ls.to_light;' \
    'WhittedIntegrator.*'
mutant spotlight-cone-inverted src/integrator/light_sample.cpp \
    'if (cos_theta < light.cos_aperture) factor = 0.0f;' \
    'if (cos_theta > light.cos_aperture) factor = 0.0f;' \
    'WhittedIntegrator.*'
mutant snell-eta-not-squared src/integrator/whitted_integrator.cpp \
    'float k = 1.0f - eta * eta * (1.0f - cos_i * cos_i);' \
    'float k = 1.0f - eta * (1.0f - cos_i * cos_i);' \
    'WhittedIntegrator.*'
mutant glass-shadow-counts-one-crossing src/integrator/glass_transmittance.h \
    'through *= crossings == 2 ? m.transparent * m.transparent : m.transparent;' \
    'through *= m.transparent;' \
    'WhittedIntegrator.*:Bvh*'
mutant sphere-u-mirrored src/shapes/unit_shapes.cpp \
    'return 0.5f - std::atan2(p.z, p.x) * (0.5f * std::numbers::inv_pi_v<float>);' \
    'return 0.5f + std::atan2(p.z, p.x) * (0.5f * std::numbers::inv_pi_v<float>);' \
    '*Uv*:*Texture*'
mutant bvh-partition-off-by-one-bin src/accel/bvh_build.cpp \
    '[&](const PrimRef& r) { return bin_of(r) < best_split; });' \
    '[&](const PrimRef& r) { return bin_of(r) <= best_split; });' \
    'Bvh*'
mutant last-tile-column-dropped src/render/renderer.cpp \
    'for (int x = r.x0; x < r.x1; x += ts) tiles.push_back({x, y, std::min(x + ts, r.x1), std::min(y + ts, r.y1)});' \
    'for (int x = r.x0; x < r.x1; x += ts) tiles.push_back({x, y, std::min(x + ts, r.x1 - 1), std::min(y + ts, r.y1)});' \
    'Renderer.*:AdaptiveAntiAliasing.*'

# --- the render contract and the distribution effects.
mutant disc-light-not-uniform src/integrator/light_sample.cpp \
    'const glm::vec2 d = light.radius * concentric_disc(u);' \
    'const glm::vec2 d = light.radius * u.x * glm::vec2(std::cos(2 * kPi * u.y), std::sin(2 * kPi * u.y));' \
    'SoftShadow.*'
mutant lens-radius-is-the-aperture src/flatten/flatten.cpp \
    'cam.lens_radius = 0.5f * desc.aperture;' \
    'cam.lens_radius = desc.aperture;' \
    'ParseDistribution.*:ThinLens.*'
mutant lens-rays-miss-the-focus-plane src/camera/camera.cpp \
    'const glm::vec3 in_focus = eye + focal_distance * through;' \
    'const glm::vec3 in_focus = eye + focal_distance * glm::normalize(through);' \
    'ThinLens.*'
mutant gloss-lobe-exponent-off-by-one src/sampler/warp.h \
    'return around_axis(axis, std::pow(1.0f - u.x, 1.0f / (e + 1.0f)), u.y);' \
    'return around_axis(axis, std::pow(1.0f - u.x, 1.0f / e), u.y);' \
    'Warp.*'
mutant sampler-ignores-the-pixel src/sampler/sampler.cpp \
    'return mix64((std::uint64_t(key.x) << 32 | key.y) ^ mix64(std::uint64_t(dim) << 32 | seed));' \
    'return mix64(std::uint64_t(key.y) ^ mix64(std::uint64_t(dim) << 32 | seed));' \
    'Sampler.*'
mutant passes-restart-the-film src/render/tile_renderer.cpp \
    's0_ = std::clamp(job.sampling.adaptive() ? 0 : job.sample_begin, 0, n);' \
    's0_ = 0;' \
    'SamplingDeterminism.*:RenderController.*'

# --- the path tracer.
mutant path-mis-ignored-on-emitter-hits src/integrator/path_integrator.cpp \
    'radiance += beta * m.emit * power_heuristic(bsdf_pdf, pdf_light);' \
    'radiance += beta * m.emit;' \
    'PathIntegrator.*:PathReference.*'
mutant path-area-density-ignores-the-matrix src/integrator/path_lights.cpp \
    'return 1.0f / (unit_shape_area(inst.kind) * area_scale(inst, n_object));' \
    'return 1.0f / unit_shape_area(inst.kind);' \
    'PathIntegrator.*:PathLights.*'
mutant path-phong-not-normalised src/integrator/bsdf.cpp \
    'if (c > 0.0f) f += weight_[1] * ((shine_ + 2.0f) / (2.0f * kPi) * std::pow(c, shine_));' \
    'if (c > 0.0f) f += weight_[1] * ((shine_ + 1.0f) / (2.0f * kPi) * std::pow(c, shine_));' \
    'Bsdf.*'
mutant path-roulette-not-compensated src/integrator/path_integrator.cpp \
    'beta /= q;' \
    '(void)q;' \
    'PathIntegrator.*:PathReference.*'

check_only=0
selected=()
for arg in "$@"; do
    case "$arg" in
        --check) check_only=1 ;;
        -h|--help) sed -n '2,17p' "$0"; exit 0 ;;
        *) selected+=("$arg") ;;
    esac
done
wanted() {
    [[ ${#selected[@]} -eq 0 ]] && return 0
    local s
    for s in "${selected[@]}"; do [[ "$s" == "$1" ]] && return 0; done
    return 1
}

# Writes FILE with the one line whose text (leading blanks ignored) is $FIND replaced by $PLANT,
# keeping its indentation, to stdout. Exit status 3 unless exactly one line matched.
plant() {
    FIND="$2" PLANT="$3" awk '
        { text = $0; sub(/^[ \t]+/, "", text) }
        text == ENVIRON["FIND"] { match($0, /^[ \t]*/); print substr($0, 1, RLENGTH) ENVIRON["PLANT"]; ++n; next }
        { print }
        END { if (n != 1) exit 3 }' "$1"
}

stale=0
for i in "${!names[@]}"; do
    wanted "${names[$i]}" || continue
    if ! plant "$root/${files[$i]}" "${finds[$i]}" "${plants[$i]}" >/dev/null; then
        echo "STALE    ${names[$i]}: '${finds[$i]}' is not exactly one line of ${files[$i]}" >&2
        stale=1
    fi
done
if [[ $check_only == 1 ]]; then
    [[ $stale == 0 ]] && echo "every mutant's line is found once"
    exit $stale
fi
[[ $stale == 0 ]] || { echo "update the stale mutants above first" >&2; exit 2; }

# The scratch copy: the tree's files (tracked and untracked, not ignored) as they are now. A file
# is copied only if it differs, with a new time stamp, so the build redoes exactly what changed.
mkdir -p "$src"
(cd "$root" && git ls-files --cached --others --exclude-standard -z) | while IFS= read -r -d '' f; do
    [[ -f "$root/$f" ]] || continue
    if ! cmp -s "$root/$f" "$src/$f"; then
        mkdir -p "$(dirname "$src/$f")"
        cp "$root/$f" "$src/$f"
    fi
done
# Files the tree no longer has go from the copy too (a deleted source would still be globbed).
if [[ -d "$src" ]]; then
    (cd "$src" && find . -type f ! -path './.git/*' -printf '%P\0') | while IFS= read -r -d '' f; do
        [[ -e "$root/$f" ]] || rm -f "$src/$f"
    done
fi
export WHITTED_SHARED_DIR="${WHITTED_SHARED_DIR:-$(cd "$root/.." && pwd)/shared}"

echo "== scratch build in $build (the first one takes a while)"
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DWHITTED_BUILD_TESTS=ON >/dev/null || exit 1
cmake --build "$build" -j"$jobs" --target whitted_tests >"$scratch/build.log" 2>&1 ||
    { echo "the unmutated copy does not build: see $scratch/build.log" >&2; exit 1; }
tests="$build/tests/whitted_tests"

survivors=()
broken=()
for i in "${!names[@]}"; do
    name="${names[$i]}" file="${files[$i]}" filter="${filters[$i]}"
    wanted "$name" || continue
    log="$scratch/$name.log"
    plant "$root/$file" "${finds[$i]}" "${plants[$i]}" >"$src/$file"
    start=$SECONDS
    if ! cmake --build "$build" -j"$jobs" --target whitted_tests >"$log" 2>&1; then
        result="BROKEN (does not build; see $log)"
        broken+=("$name")
    elif timeout 900 "$tests" --gtest_filter="$filter" --gtest_brief=1 >>"$log" 2>&1; then
        result="SURVIVED (tests $filter passed; see $log)"
        survivors+=("$name")
    else
        code=$?
        failed="$(grep -cE '^\[  FAILED  \] [A-Za-z].* \([0-9]+ ms\)$' "$log")"
        if [[ $failed -gt 0 ]]; then result="caught by $failed failing test(s) of $filter"
        elif [[ $code -eq 124 ]]; then result="caught: $filter timed out (900 s)"
        else result="caught: $filter exited with $code"; fi
    fi
    cp "$root/$file" "$src/$file"  # put the line back (a new time stamp: rebuilt next time)
    printf '%-45s %s (%ds)\n' "$name" "$result" $((SECONDS - start))
done
# Leave the scratch build unmutated.
cmake --build "$build" -j"$jobs" --target whitted_tests >"$scratch/build.log" 2>&1

echo "== ${#survivors[@]} survived${survivors[*]:+: ${survivors[*]}}; ${#broken[@]} did not build${broken[*]:+: ${broken[*]}}"
[[ ${#survivors[@]} -eq 0 && ${#broken[@]} -eq 0 ]]
exit
}

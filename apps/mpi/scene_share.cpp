#include "scene_share.h"

#include <mpi.h>

#include <chrono>
#include <climits>
#include <cstring>
#include <iostream>
#include <vector>

#include "film/image_io.h"
#include "load_report.h"
#include "base/read_file.h"
#include "tiles.h"

namespace whitted::mpi {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::uint64_t file_hash(const char* path) {
    const FileContents file = read_regular_file(path, std::size_t(1) << 30);
    return fnv1a(file.bytes);
}

// MPI counts are ints: large payloads go in pieces.
void broadcast_bytes(std::vector<char>& bytes, int root) {
    std::uint64_t size = bytes.size();
    MPI_Bcast(&size, 1, MPI_UINT64_T, root, MPI_COMM_WORLD);
    bytes.resize(size);
    constexpr std::uint64_t kPiece = 1u << 30;
    for (std::uint64_t at = 0; at < size; at += kPiece)
        MPI_Bcast(bytes.data() + at, int(std::min(kPiece, size - at)), MPI_BYTE, root, MPI_COMM_WORLD);
}

void put(std::vector<char>& out, const std::string& s) {
    const std::uint64_t n = s.size();
    out.insert(out.end(), reinterpret_cast<const char*>(&n), reinterpret_cast<const char*>(&n) + sizeof n);
    out.insert(out.end(), s.begin(), s.end());
}

bool get(const char*& p, const char* end, std::string& s) {
    std::uint64_t n = 0;
    if (std::size_t(end - p) < sizeof n) return false;
    std::memcpy(&n, p, sizeof n);
    p += sizeof n;
    if (std::uint64_t(end - p) < n) return false;
    s.assign(p, std::size_t(n));
    p += n;
    return true;
}

void put_files(std::vector<char>& out, const TextureFiles& files) {
    put(out, std::to_string(files.size()));
    for (const auto& [name, bytes] : files) {
        put(out, name);
        put(out, std::string(bytes.begin(), bytes.end()));
    }
}

bool get_files(const char*& p, const char* end, TextureFiles& files) {
    std::string count;
    if (!get(p, end, count)) return false;
    for (long i = 0, n = std::stol(count); i < n; ++i) {
        std::string name, bytes;
        if (!get(p, end, name) || !get(p, end, bytes)) return false;
        files[name].assign(bytes.begin(), bytes.end());
    }
    return true;
}

// The scene text, each texture file and each mesh file: [text][count][name, bytes]...[count][name, bytes]...
// (every input byte: the ranks read no file of their own, and the job's hash covers them all).
std::vector<char> pack(const std::string& text, const TextureFiles& textures, const TextureFiles& meshes) {
    std::vector<char> out;
    put(out, text);
    put_files(out, textures);
    put_files(out, meshes);
    return out;
}

bool unpack(const std::vector<char>& in, std::string& text, TextureFiles& textures, TextureFiles& meshes) {
    const char* p = in.data();
    const char* end = p + in.size();
    return get(p, end, text) && get_files(p, end, textures) && get_files(p, end, meshes);
}

}  // namespace

bool same_binary_and_options(int argc, char** argv, int rank, int ranks) {
    std::string args;
    for (int i = 1; i < argc; ++i) args += std::string(argv[i]) + '\0';
    const std::uint64_t mine[2] = {file_hash("/proc/self/exe"), fnv1a(args)};
    std::vector<std::uint64_t> all(std::size_t(2 * ranks));
    MPI_Gather(mine, 2, MPI_UINT64_T, all.data(), 2, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    int ok = 1;
    if (rank == 0)
        for (int r = 1; r < ranks && ok; ++r) {
            if (all[std::size_t(2 * r)] != mine[0]) {
                std::cerr << "whitted-mpi: error: rank " << r << " runs another whitted-mpi executable than rank 0 "
                          << "(install the same build on every node)\n";
                ok = 0;
            } else if (all[std::size_t(2 * r + 1)] != mine[1]) {
                std::cerr << "whitted-mpi: error: rank " << r << " was started with other options than rank 0\n";
                ok = 0;
            }
        }
    MPI_Bcast(&ok, 1, MPI_INT, 0, MPI_COMM_WORLD);
    return ok == 1;
}

SharedScene share_scene(const cli::RenderOptions& o, int rank, const std::atomic<bool>* cancel,
                        const cli::SessionLimits* limits, bool again) {
    SharedScene s;
    LoadOptions lo = cli::load_options(o, cancel);
    std::vector<char> payload;
    const auto start = Clock::now();
    if (rank == 0) {
        // Only regular files, within the size limit, stoppable (a FIFO or /dev/zero is refused).
        FileContents file = read_scene_file(o.scene_path, lo);
        // An unreadable file: the library's own load says so, as whitted would.
        lo.textures.keep_files = true;
        if (std::string problem = output_unwritable(o.output); !problem.empty()) {
            // A missing folder is found now, not after the render (rank 0 writes the image).
            std::cerr << "whitted-mpi: error: " << problem << "\n";
            s.code = cli::kExitIo;
        } else {
            s.loaded = !file.ok() ? load_scene(o.scene_path, lo) : load_scene_text(file.bytes, o.scene_path, lo);
            s.code = again && s.loaded.ok()
                         ? cli::kExitOk
                         : cli::report_load(s.loaded, o, "whitted-mpi", limits ? limits->ran_out() : nullptr);
            if (s.code == cli::kExitTimeout) s.code = cli::kExitInterrupted;  // here 4 means two ranks disagreed
        }
        if (s.code == 0) payload = pack(file.bytes, s.loaded.texture_files, s.loaded.mesh_files);
        s.loaded.texture_files.clear();
        s.loaded.mesh_files.clear();
        s.load_seconds = since(start);
    }
    MPI_Bcast(&s.code, 1, MPI_INT, 0, MPI_COMM_WORLD);
    if (s.code != 0) return s;
    const auto bcast = Clock::now();
    broadcast_bytes(payload, 0);
    s.broadcast_seconds = since(bcast);
    s.bytes = payload.size();
    s.hash = fnv1a(std::string_view(payload.data(), payload.size()));
    if (rank != 0) {
        const auto t = Clock::now();
        std::string text;
        TextureFiles files, meshes;
        int code = 0;
        if (!unpack(payload, text, files, meshes)) {
            code = cli::kExitIo;
        } else {
            payload = {};
            lo.textures.preread = &files;
            lo.preread_meshes = &meshes;
            s.loaded = load_scene_text(text, o.scene_path, lo);
            if (!s.loaded.ok()) code = s.loaded.cancelled ? cli::kExitInterrupted : cli::kExitScene;
        }
        s.load_seconds = since(t);
        s.code = code;
    }
    // A rank that could not build what rank 0 could (out of memory, interrupted) stops them all.
    int worst = s.code;
    MPI_Allreduce(&s.code, &worst, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    if (worst != 0 && s.code == 0 && rank == 0)
        std::cerr << "whitted-mpi: error: another rank could not build the scene (exit code " << worst << ")\n";
    s.code = worst;
    return s;
}

}  // namespace whitted::mpi

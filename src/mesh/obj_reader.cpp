#include "mesh/obj_reader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "base/read_file.h"
#include "mesh/obj_line.h"
#include "mesh/polygon_split.h"

namespace whitted {
namespace {

// The lines of the text, from memory or from a file read 64 KiB at a time (never held whole; a
// line longer than a piece makes the piece grow to hold it). Lines end at \n, \r\n and a lone \r
// alike. Between pieces (every 64 KiB of text in memory) the cancel flag and a reason of our own
// to stop are looked at; the number of the last line given and where it ended are always known.
class LineSource {
public:
    static constexpr std::size_t kPiece = 64 << 10;

    LineSource(std::string_view text, const std::atomic<bool>* cancel)
        : data_(text.data()), size_(text.size()), eof_(true), next_look_(kPiece), cancel_(cancel) {}
    LineSource(FileReader& file, const std::atomic<bool>* cancel) : file_(&file), piece_(kPiece), cancel_(cancel) {
        data_ = piece_.data();
    }
    // The text ends early once `*stop` is set.
    void stop_when(const bool* stop) { stop_ = stop; }
    bool cancelled() const { return cancel_ && cancel_->load(std::memory_order_relaxed); }
    // Why the file could not be read to its end ("" if it was, or the text is in memory).
    std::string read_error() const { return file_ && !file_->info().cancelled ? file_->info().error : std::string(); }
    // Bytes of the text held in memory: all of it, or the piece read.
    std::size_t held() const { return file_ ? piece_.size() : size_; }
    // The 1-based number of the last line given, and the offset in the text just past its break.
    int line() const { return line_; }
    std::size_t offset() const { return base_ + at_; }

    // The next line, without its break; false at the end of the text, or to stop.
    bool next(std::string_view& line) {
        for (;;) {
            if (base_ + at_ >= next_look_ && !look()) return false;
            const char* p = data_ + at_;
            const char* e = data_ + size_;
            if (p == e) {  // (no text at all may be a null pointer: not searched)
                if (eof_ || !refill()) return false;
                continue;
            }
            // The first \n, or a \r before it.
            const char* nl = static_cast<const char*>(std::memchr(p, '\n', std::size_t(e - p)));
            const char* q = nl ? nl : e;
            if (const void* cr = std::memchr(p, '\r', std::size_t(q - p))) q = static_cast<const char*>(cr);
            // A line ends at its break, or at the end of the text; a \r the piece's last byte
            // waits for the next piece (a \n after it is part of the same break).
            if (q < e && !(*q == '\r' && q + 1 == e && !eof_)) {
                line = std::string_view(p, std::size_t(q - p));
                at_ = std::size_t(q - data_) + 1 + (*q == '\r' && q + 1 < e && q[1] == '\n');
                ++line_;
                return true;
            }
            if (eof_) {
                if (p == e) return false;
                line = std::string_view(p, std::size_t(e - p));
                at_ = size_;
                ++line_;
                return true;
            }
            if (!refill()) return false;
        }
    }

private:
    bool look() {
        next_look_ = base_ + at_ + kPiece;
        return !((stop_ && *stop_) || cancelled());
    }
    // The unread part moved to the front and the rest of the piece read (the piece doubled when
    // one line fills it).
    bool refill() {
        if (!look()) return false;
        const std::size_t keep = size_ - at_;
        if (keep == piece_.size()) piece_.resize(2 * piece_.size());
        std::memmove(piece_.data(), piece_.data() + at_, keep);
        base_ += at_;
        at_ = 0;
        data_ = piece_.data();
        const std::size_t n = file_->read(piece_.data() + keep, piece_.size() - keep);
        size_ = keep + n;
        if (n == 0) eof_ = true;
        return true;
    }

    FileReader* file_ = nullptr;
    std::vector<char> piece_;
    const char* data_ = nullptr;  // the text in memory, or the piece
    std::size_t size_ = 0;        // of data_
    std::size_t at_ = 0;          // where the next line starts in data_
    std::size_t base_ = 0;        // offset of data_ in the text
    bool eof_ = false;            // data_ holds the text's end
    std::size_t next_look_ = 0;   // the offset at which to look at the flags again
    int line_ = 0;
    const std::atomic<bool>* cancel_;
    const bool* stop_ = nullptr;
};

constexpr const char* kNames[3] = {"vertex", "texture coordinate", "normal"};

// A corner of a face: indices into the file's v, vt and vn (0-based; -1 for vt, vn: none).
struct Corner {
    std::int32_t index[3];
};

bool finite(const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// A vertex of the mesh: a distinct (v, vn, vt) of the file's corners (kNoIndex for none).
constexpr std::uint32_t kNoIndex = 0xffffffffu;
struct CornerKey {
    std::uint32_t v, n, t;
    bool operator==(const CornerKey&) const = default;
};

// The mesh vertex of each distinct corner key, numbered in order of first use. The first key of
// each file position is found by the position's number (faces name positions near each other, so
// that look-up stays in the cache); the others (a seam's second uv, a crease's second normal) in
// an open-addressing table of vertex numbers. Each vertex's key is kept in vertex order (about 16
// bytes a vertex with the position's slot). A node-based map cost about 64 bytes a vertex in
// small heap blocks, which the allocator kept after they were freed, so that the BVH build that
// follows started from a resident heap the size of the map.
class VertexTable {
public:
    void reserve(std::size_t vertices, std::size_t positions) {
        keys_.reserve(vertices);
        first_.reserve(positions);
        std::size_t size = 16;
        while (size < vertices / 8) size *= 2;  // a sixteenth of them on seams, half full; it grows
        if (size > slots_.size()) rehash(size);
    }
    // The vertex of `key`; a new one when `added`.
    std::uint32_t find_or_add(const CornerKey& key, bool& added) {
        if (key.v >= first_.size()) first_.resize(std::size_t(key.v) + 1, kNoIndex);
        std::uint32_t& first = first_[key.v];
        added = false;
        if (first == kNoIndex) {
            added = true;
            return first = add(key);
        }
        if (keys_[first] == key) return first;
        if ((count_ + 1) * 2 > slots_.size()) rehash(std::max<std::size_t>(16, slots_.size() * 2));
        const std::size_t mask = slots_.size() - 1;
        for (std::size_t i = hash(key) & mask;; i = (i + 1) & mask) {
            const std::uint32_t s = slots_[i];
            if (s == kNoIndex) {
                ++count_;
                added = true;
                return slots_[i] = add(key);
            }
            if (keys_[s] == key) return s;
        }
    }
    std::size_t bytes() const {
        return keys_.capacity() * sizeof(CornerKey) + (first_.capacity() + slots_.capacity()) * sizeof(std::uint32_t);
    }
    void release() {
        BigVector<CornerKey>().swap(keys_);
        BigVector<std::uint32_t>().swap(first_);
        BigVector<std::uint32_t>().swap(slots_);
        count_ = 0;
    }

private:
    std::uint32_t add(const CornerKey& key) {
        keys_.push_back(key);
        return std::uint32_t(keys_.size() - 1);
    }
    static std::size_t hash(const CornerKey& k) {
        std::uint64_t h = k.v * 0x9E3779B97F4A7C15ull;
        h ^= (h >> 29) + k.n * 0xBF58476D1CE4E5B9ull;
        h ^= (h >> 31) + k.t * 0x94D049BB133111EBull;
        return std::size_t(h ^ (h >> 32));
    }
    void rehash(std::size_t size) {
        BigVector<std::uint32_t> old(size, kNoIndex);
        old.swap(slots_);
        const std::size_t mask = size - 1;
        for (std::uint32_t k : old)
            if (k != kNoIndex) {
                std::size_t i = hash(keys_[k]) & mask;
                while (slots_[i] != kNoIndex) i = (i + 1) & mask;
                slots_[i] = k;
            }
    }
    BigVector<CornerKey> keys_;       // of each vertex
    BigVector<std::uint32_t> first_;  // per file position: its first vertex (kNoIndex: none yet)
    BigVector<std::uint32_t> slots_;  // the other keys' vertices
    std::size_t count_ = 0;           // in slots_
};

// Triangles with the same three positions in the same order as one kept before: the same triangle
// to every ray (the same arithmetic gives the same hit, and of equal hits the first is taken), so
// drawing it again only costs; a file of a million copies of one triangle made every ray that
// met it test them all. An open-addressing table of triangle numbers, hashed by position bits,
// each beside 32 more bits of its hash: a probe that meets another triangle is told apart there,
// without the three positions' cache misses (nearly every triangle of a file is new).
class SameTriangles {
public:
    explicit SameTriangles(std::size_t expected) {
        std::size_t size = 16;
        while (size < 2 * expected) size *= 2;
        slots_.assign(size, kEmpty);
    }
    // True if a triangle of `mesh` has the corners p; else remembers that triangle `next` will.
    bool repeats(const TriangleMesh& mesh, const glm::vec3* const (&p)[3], std::uint32_t next) {
        if ((count_ + 1) * 2 > slots_.size()) grow(mesh);  // (before `next` is in the table: not in the mesh yet)
        const std::size_t mask = slots_.size() - 1;
        const std::uint64_t h = hash(p), tag = h & 0xffffffff00000000ull;
        for (std::size_t i = std::size_t(h) & mask;; i = (i + 1) & mask) {
            const std::uint64_t slot = slots_[i];
            if (slot == kEmpty) {
                slots_[i] = tag | next;
                ++count_;
                return false;
            }
            if ((slot & 0xffffffff00000000ull) != tag) continue;
            const TriangleIndices& t = mesh.triangles[std::uint32_t(slot)];
            if (same(mesh.positions[t[0]], *p[0]) && same(mesh.positions[t[1]], *p[1]) &&
                same(mesh.positions[t[2]], *p[2]))
                return true;
        }
    }
    std::size_t bytes() const { return slots_.capacity() * sizeof(std::uint64_t); }

private:
    static constexpr std::uint64_t kEmpty = ~std::uint64_t(0);  // (no triangle is number 2^32 - 1)
    // The low bits pick the slot, the high 32 are kept in it.
    static std::uint64_t hash(const glm::vec3* const (&p)[3]) {
        std::uint64_t h = 0x84222325cbf29ce4ull;
        for (const glm::vec3* c : p)
            for (int a = 0; a < 3; ++a) {
                std::uint32_t bits;
                std::memcpy(&bits, &(*c)[a], sizeof bits);
                h = (h ^ bits) * 0x100000001b3ull;
            }
        h ^= h >> 29;
        return h * 0xbf58476d1ce4e5b9ull;
    }
    static bool same(const glm::vec3& a, const glm::vec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }
    void grow(const TriangleMesh& mesh) {
        BigVector<std::uint64_t> old(slots_.size() * 2, kEmpty);
        old.swap(slots_);
        const std::size_t mask = slots_.size() - 1;
        for (std::uint64_t slot : old)
            if (slot != kEmpty) {
                const TriangleIndices& c = mesh.triangles[std::uint32_t(slot)];
                const glm::vec3* const p[3] = {&mesh.positions[c[0]], &mesh.positions[c[1]], &mesh.positions[c[2]]};
                std::size_t i = std::size_t(hash(p)) & mask;
                while (slots_[i] != kEmpty) i = (i + 1) & mask;
                slots_[i] = slot;
            }
    }
    BigVector<std::uint64_t> slots_;  // on 2 MB pages: each probe is a miss, not a TLB miss too
    std::size_t count_ = 0;
};

std::string memory_error(std::size_t limit) {
    return "the mesh needs more than the " + describe_bytes(limit) +
           " of memory left for it (--max-memory; a scene's objects, textures and meshes share it)";
}

// How many of each kind of line the text has (a line's first word only): what the arrays are
// reserved for before the parse, so that none of them grows by doubling (up to twice its size,
// and a copy) on a big file. A hint: a line the parse reads otherwise only costs a regrowth.
// Fed the text in pieces, in order.
struct LineCounts {
    std::size_t v = 0, vn = 0, vt = 0, f = 0;

    void feed(const char* p, const char* end) {
        while (p < end) {
            if (!in_line_) {
                if (!first_) {
                    while (p < end && (*p == ' ' || *p == '\t')) ++p;
                    if (p == end) return;
                    first_ = *p++;
                    if (first_ == '\n') {  // an empty line
                        first_ = 0;
                        continue;
                    }
                    if (p == end) return;
                }
                const char second = *p;  // (not taken: it may end the line)
                if (first_ == 'v') {
                    v += second == ' ' || second == '\t';
                    vn += second == 'n';
                    vt += second == 't';
                } else if (first_ == 'f') {
                    f += second == ' ' || second == '\t';
                }
                first_ = 0;
                in_line_ = true;
            }
            const void* nl = std::memchr(p, '\n', std::size_t(end - p));
            if (!nl) return;
            p = static_cast<const char*>(nl) + 1;
            in_line_ = false;
        }
    }

private:
    bool in_line_ = false;  // past a line's first word
    char first_ = 0;        // a line's first character, when a piece ended after it
};

// The parse and the mesh made as it goes, a line at a time. A face is split into triangles and
// its corners made vertices as soon as it is read, so that no copy of every corner is held while
// the mesh is made: of a file's
// own arrays only its v, vn and vt stay (the faces look them up anywhere behind them). Faces from
// the first one naming a definition further down (OBJ allows it) are kept, and made triangles in
// file order once the file is read.
struct Parse {
    LineSource* buffer = nullptr;
    TriangleMesh* mesh = nullptr;
    ObjReadResult* result = nullptr;
    std::vector<glm::vec3> v, vn;
    std::vector<glm::vec2> vt;
    // Each mesh vertex is one distinct (v, vn, vt) of the file's corners (split where a seam gives
    // one position two uvs), so a triangle costs one index triple, as pbrt and Embree keep meshes.
    VertexTable vertices;
    SameTriangles seen{0};
    std::vector<Corner> face;  // the face being read
    std::vector<glm::vec3> polygon;
    std::vector<std::array<std::uint32_t, 3>> split;
    bool deferring = false;          // a face named a definition further down: faces are kept from it on
    std::vector<Corner> corners;     // of the kept faces
    std::vector<std::uint32_t> face_size;
    std::size_t used = 0, limit = 0;  // bytes
    bool stop = false;                // a reason to stop reading (memory, cancel)
    std::string error;                // the first bad face (the parse goes on: later definitions count)
    std::size_t error_at = 0;         // its offset in the text
    int error_line = 0;
    std::size_t faces = 0, next_look = 0;
    // Faces naming a definition further down: checked once the file is read.
    struct Ahead {
        std::size_t at;
        int line;
        std::int64_t index[3];  // the largest index of each kind named, 0-based
    };
    std::vector<Ahead> ahead;

    std::size_t count(int kind) const { return kind == 0 ? v.size() : kind == 1 ? vt.size() : vn.size(); }
    // What is held now (the arrays as allocated, not as filled) with the mesh's BVH to come
    // (kMeshBvhBytesPerTriangle), and `transient` more for a moment.
    void spend(std::size_t transient = 0) {
        used = buffer->held() + (v.capacity() + vn.capacity()) * sizeof(glm::vec3) + vt.capacity() * sizeof(glm::vec2) +
               corners.capacity() * sizeof(Corner) + face_size.capacity() * sizeof(std::uint32_t) +
               ahead.capacity() * sizeof(Ahead) + vertices.bytes() + seen.bytes() + mesh->memory_bytes() +
               mesh->triangles.size() * kMeshBvhBytesPerTriangle;
        if (used + transient > limit) stop = true;
    }
    // Looked at every 1,024 faces and every 16,384 triangles (one face may be millions of them).
    bool should_stop() {
        next_look = mesh->triangles.size() + 16384;
        if (buffer->cancelled()) stop = true;
        else spend();
        return stop;
    }
    void bad_face(const std::string& why) {
        if (!error.empty()) return;
        error = why;
        error_at = buffer->offset();
        error_line = buffer->line();
    }

    std::uint32_t vertex(const Corner& c) {
        const CornerKey key{std::uint32_t(c.index[0]), c.index[2] >= 0 ? std::uint32_t(c.index[2]) : kNoIndex,
                            c.index[1] >= 0 ? std::uint32_t(c.index[1]) : kNoIndex};
        bool added = false;
        const std::uint32_t i = vertices.find_or_add(key, added);
        if (!added) return i;
        mesh->positions.push_back(v[key.v]);
        // A corner without vn holds the normal (0, 0, 0), without vt the uv (NaN, NaN) (its
        // triangle then takes its geometric normal, or uv (0, 0), as §9.3 says); once the file
        // has given one, every vertex has one (those made before: none), and at the end all do.
        if (!vn.empty()) {
            mesh->normals.resize(i, glm::vec3(0.0f));
            mesh->normals.push_back(key.n != kNoIndex ? vn[key.n] : glm::vec3(0.0f));
        }
        if (!vt.empty()) {
            mesh->uvs.resize(i, glm::vec2(std::numeric_limits<float>::quiet_NaN()));
            mesh->uvs.push_back(key.t != kNoIndex ? vt[key.t] : glm::vec2(std::numeric_limits<float>::quiet_NaN()));
        }
        return i;
    }

    // The triangles of a face whose corners are all defined; false to stop.
    bool add_face(const Corner* c, std::uint32_t n) {
        if ((faces++ % 1024 == 0 || mesh->triangles.size() >= next_look) && should_stop()) return false;
        polygon.resize(n);
        for (std::uint32_t k = 0; k < n; ++k) polygon[k] = v[std::size_t(c[k].index[0])];
        split.clear();
        split_polygon(polygon.data(), n, split);
        if (n > kEarClipCorners) ++result->fans;
        for (const auto& tri : split) {
            const glm::vec3* const p[3] = {&polygon[tri[0]], &polygon[tri[1]], &polygon[tri[2]]};
            const glm::vec3 normal = glm::cross(*p[1] - *p[0], *p[2] - *p[0]);
            if (!finite(*p[0]) || !finite(*p[1]) || !finite(*p[2]) || !(glm::dot(normal, normal) > 0.0f)) {
                ++result->degenerate;
                continue;
            }
            if (seen.repeats(*mesh, p, std::uint32_t(mesh->triangles.size()))) {
                ++result->duplicates;
                continue;
            }
            mesh->triangles.push_back({vertex(c[tri[0]]), vertex(c[tri[1]]), vertex(c[tri[2]])});
            if (mesh->triangles.size() >= next_look && should_stop()) return false;
        }
        return true;
    }
};

// A face: its raw OBJ indices (1-based; negative count back from the last definition so far; 0 is
// none for vt and vn, and for v either a 0 or no number at all) made 0-based and checked.
void on_face(Parse& s, const ObjCorner* raw, int n) {
    if (s.stop || !s.error.empty()) return;
    // The line's corners are held too while this runs.
    s.spend(std::size_t(n) * (sizeof(ObjCorner) + 2 * sizeof(Corner)));
    if (s.stop) return;
    std::int64_t ahead[3] = {-1, -1, -1};
    s.face.clear();
    for (int c = 0; c < n; ++c) {
        const int given[3] = {raw[c].v, raw[c].vt, raw[c].vn};
        Corner corner{};
        for (int k = 0; k < 3; ++k) {
            const std::int64_t r = given[k], defined = std::int64_t(s.count(k));
            std::int64_t i = -1;
            if (r > 0) {
                i = r - 1;
                if (i >= defined) ahead[k] = std::max(ahead[k], i);
            } else if (r < 0) {
                i = defined + r;
                if (i < 0) {
                    s.bad_face("face refers to " + std::string(kNames[k]) + " " + std::to_string(r) +
                               ", but the file defines " + std::to_string(defined) +
                               " before this line (indices start at 1; negative ones count back)");
                    break;
                }
            } else if (k == 0) {
                s.bad_face("a face has vertex index 0 or no number where a vertex index belongs (indices start "
                           "at 1; negative ones count back)");
                break;
            }
            corner.index[k] = std::int32_t(i);
        }
        if (!s.error.empty()) break;
        s.face.push_back(corner);
    }
    if (!s.error.empty() || n < 3) return;  // a face of one or two corners draws nothing
    const bool names_ahead = ahead[0] >= 0 || ahead[1] >= 0 || ahead[2] >= 0;
    if (!names_ahead && !s.deferring) {
        s.add_face(s.face.data(), std::uint32_t(n));
        return;
    }
    s.deferring = true;
    s.corners.insert(s.corners.end(), s.face.begin(), s.face.end());
    s.face_size.push_back(std::uint32_t(n));
    if (names_ahead) s.ahead.push_back({s.buffer->offset(), s.buffer->line(), {ahead[0], ahead[1], ahead[2]}});
    s.spend();
}

template <class T>
void release(std::vector<T>& v) {
    std::vector<T>().swap(v);
}

// Reads the OBJ text `buffer` gives (counted ahead in `lines`) into `mesh`, which is left
// cleared by the callers whenever this fails.
ObjReadResult read_obj_into(LineSource& buffer, const LineCounts& lines, const std::string& name, TriangleMesh& mesh,
                            const ObjLimits& limits) {
    ObjReadResult result;
    mesh = TriangleMesh();
    mesh.path = name;
    Parse s;
    s.buffer = &buffer;
    buffer.stop_when(&s.stop);
    s.mesh = &mesh;
    s.result = &result;
    s.limit = limits.max_bytes;
    s.spend();  // the text is held while the rest is made
    if (s.stop) {
        result.error = memory_error(limits.max_bytes);
        return result;
    }
    s.v.reserve(lines.v);
    s.vn.reserve(lines.vn);
    s.vt.reserve(lines.vt);
    // A vertex per position, and a few more where seams split one; no more than the faces'
    // corners can make (a file of positions alone reserves no mesh for them).
    const std::size_t vertices = std::min(lines.v + lines.v / 16, 3 * lines.f);
    s.vertices.reserve(vertices, lines.v);
    mesh.positions.reserve(vertices);
    if (lines.vn) mesh.normals.reserve(vertices);
    if (lines.vt) mesh.uvs.reserve(vertices);
    mesh.triangles.reserve(lines.f);
    s.seen = SameTriangles(lines.f);
    s.spend();
    if (s.stop) {
        result.error = memory_error(limits.max_bytes);
        return result;
    }

    // `mtllib` and `usemtl` are ignored (the scene's material applies), as are `o`, `g` and `s`.
    std::string_view text;
    ObjLine line;
    while (!s.stop && buffer.next(text)) {
        parse_obj_line(text, line);
        switch (line.kind) {
        case ObjLineKind::Vertex:
            s.v.emplace_back(line.xyz[0], line.xyz[1], line.xyz[2]);
            s.spend();
            break;
        case ObjLineKind::Normal:
            s.vn.emplace_back(line.xyz[0], line.xyz[1], line.xyz[2]);
            s.spend();
            break;
        case ObjLineKind::TexCoord:
            s.vt.emplace_back(line.xyz[0], line.xyz[1]);
            s.spend();
            break;
        case ObjLineKind::Face:
            if (!line.corners.empty()) on_face(s, line.corners.data(), int(line.corners.size()));
            break;
        case ObjLineKind::Other:
            break;
        }
    }
    if (buffer.cancelled()) {
        result.cancelled = true;
        return result;
    }
    if (const std::string why = buffer.read_error(); !why.empty()) {
        result.error = why;
        return result;
    }
    if (s.stop) {
        result.error = memory_error(limits.max_bytes);
        return result;
    }
    // The first bad face of the file: one found as it was read, or one naming a definition
    // further down that never came.
    for (const Parse::Ahead& a : s.ahead) {
        if (!s.error.empty() && a.at >= s.error_at) break;
        int kind = 0;
        while (kind < 3 && a.index[kind] < std::int64_t(s.count(kind))) ++kind;
        if (kind == 3) continue;
        s.error = "face refers to " + std::string(kNames[kind]) + " " + std::to_string(a.index[kind] + 1) +
                  ", but the file has " + std::to_string(s.count(kind)) +
                  " (indices start at 1; negative ones count back)";
        s.error_at = a.at;
        s.error_line = a.line;
        break;
    }
    if (!s.error.empty()) {
        result.error = s.error;
        result.line = s.error_line;
        return result;
    }
    release(s.ahead);

    // The faces kept, now that everything they name is defined.
    std::size_t corner = 0;
    for (std::uint32_t n : s.face_size) {
        if (!s.add_face(&s.corners[corner], n)) {
            if (buffer.cancelled()) result.cancelled = true;
            else result.error = memory_error(limits.max_bytes);
            return result;
        }
        corner += n;
    }
    release(s.corners);
    release(s.face_size);
    s.vertices.release();
    s.seen = SameTriangles(0);
    if (!s.vn.empty()) mesh.normals.resize(mesh.positions.size(), glm::vec3(0.0f));
    if (!s.vt.empty()) mesh.uvs.resize(mesh.positions.size(), glm::vec2(std::numeric_limits<float>::quiet_NaN()));
    release(s.v);
    release(s.vn);
    release(s.vt);
    if (mesh.triangles.empty()) {
        result.error = result.degenerate > 0 ? "the file's " + std::to_string(result.degenerate) +
                                                   " triangles all have zero area: no triangle to draw"
                                             : "the file holds no triangle (no 'f' face with three or more vertices)";
        return result;
    }
    mesh.positions.shrink_to_fit();
    mesh.triangles.shrink_to_fit();
    mesh.normals.shrink_to_fit();
    mesh.uvs.shrink_to_fit();
    result.bytes = mesh.memory_bytes() + mesh.triangles.size() * kMeshBvhBytesPerTriangle;
    if (result.bytes > limits.max_bytes) {
        mesh = TriangleMesh();
        result.error = memory_error(limits.max_bytes);
        return result;
    }
    result.ok = true;
    return result;
}

}  // namespace

ObjReadResult read_obj_text(std::string_view text, const std::string& name, TriangleMesh& mesh,
                            const ObjLimits& limits) {
    LineCounts lines;
    lines.feed(text.data(), text.data() + text.size());
    LineSource buffer(text, limits.cancel);
    ObjReadResult result = read_obj_into(buffer, lines, name, mesh, limits);
    if (!result.ok) mesh = TriangleMesh();  // nothing half-made is left
    return result;
}

ObjReadResult read_obj_file(FileReader& file, const std::string& name, TriangleMesh& mesh, const ObjLimits& limits) {
    // The pieces read twice: counted first (a hint for the arrays), then parsed.
    LineCounts lines;
    std::vector<char> piece(LineSource::kPiece);
    const std::size_t start = file.position();
    for (std::size_t n; (n = file.read(piece.data(), piece.size())) > 0;) lines.feed(piece.data(), piece.data() + n);
    file.seek(start);
    std::vector<char>().swap(piece);
    LineSource buffer(file, limits.cancel);
    ObjReadResult result = read_obj_into(buffer, lines, name, mesh, limits);
    if (!result.ok) mesh = TriangleMesh();
    return result;
}

ObjReadResult read_obj(const std::string& path, TriangleMesh& mesh, const ObjLimits& limits) {
    FileReader file(path, limits.max_file_bytes, limits.cancel);
    if (!file.ok()) {
        ObjReadResult r;
        r.cancelled = file.info().cancelled;
        if (!r.cancelled) r.error = "cannot read '" + path + "': " + file.info().error;
        return r;
    }
    ObjReadResult r = read_obj_file(file, path, mesh, limits);
    if (!r.ok && !r.cancelled && r.line == 0 && !file.info().error.empty()) r.error = "cannot read '" + path + "': " + r.error;
    return r;
}

}  // namespace whitted

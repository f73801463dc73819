// The checkpoint of whitted and whitted-mpi: the tiles written come back with the same bytes; a
// record cut short by a kill, or damaged, is dropped (that tile is rendered again); another job's
// file is refused, saying what differs; a good file is replaced only whole; a render in passes
// goes on from the most whole passes a file holds.
#include <sys/stat.h>

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "session/checkpoint.h"
#include "support/run_process.h"

namespace whitted {
namespace {

const TileGrid kGrid{20, 10, 8};  // 3 × 2 tiles, the last column and row cut short
const std::string kSettings = "width=20;height=10;spp=4;time=0;tile=8;";
constexpr int kSamples = 4;

CheckpointKey key(std::uint64_t inputs = 7, TileGrid grid = kGrid, std::string settings = kSettings) {
    return {settings, inputs, grid};
}

Film numbered_film() {
    Film f(kGrid.width, kGrid.height);
    for (int y = 0; y < kGrid.height; ++y)
        for (int x = 0; x < kGrid.width; ++x) f.at(x, y) = {glm::vec3(x, y, 0.1f * float(x * y)), float(x + 3)};
    return f;
}

std::string write(const std::string& path, const std::vector<int>& tiles, std::uint64_t hash = 7) {
    const Film f = numbered_film();
    CheckpointWriter w;
    EXPECT_EQ(w.open(path, key(hash), {}, 100), "");
    for (int t : tiles) w.append(t, f, kSamples);
    return path;
}

void expect_tile(const Film& got, int t, bool filled) {
    const Film want = numbered_film();
    const Tile r = kGrid.tile(t);
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) {
            const FilmPixel& p = got.at(x, y);
            if (filled)
                ASSERT_EQ(std::memcmp(&p, &want.at(x, y), sizeof p), 0) << x << "," << y;
            else
                ASSERT_EQ(p.weight, 0.0f);
        }
}

TEST(Checkpoint, TilesComeBackByteForByte) {
    const std::string path = write(test::make_temp_dir() + "/ck", {5, 0, 3});
    Film f(kGrid.width, kGrid.height);
    std::vector<bool> done;
    ASSERT_EQ(read_checkpoint(path, key(), kSamples, f, done), "");
    EXPECT_EQ(done, (std::vector<bool>{true, false, false, true, false, true}));
    for (int t = 0; t < kGrid.count(); ++t) expect_tile(f, t, done[std::size_t(t)]);
}

TEST(Checkpoint, ARecordCutShortOrDamagedIsDropped) {
    const std::string path = write(test::make_temp_dir() + "/ck", {0, 1, 2});
    const auto size = std::filesystem::file_size(path);
    // Each record: index, samples, the tile's pixels, checksum. Tile 2 is 4 × 8 pixels.
    const std::size_t last = 4 + 4 + 4 * 8 * sizeof(FilmPixel) + 8;
    std::filesystem::resize_file(path, size - 1);
    Film f(kGrid.width, kGrid.height);
    std::vector<bool> done;
    ASSERT_EQ(read_checkpoint(path, key(), kSamples, f, done), "");
    EXPECT_EQ(done, (std::vector<bool>{true, true, false, false, false, false}));
    expect_tile(f, 2, false);

    {  // one flipped byte inside tile 1's pixels
        std::fstream io(path, std::ios::in | std::ios::out | std::ios::binary);
        io.seekp(std::streamoff(size - last - 20));
        io.put('\x55');
    }
    Film g(kGrid.width, kGrid.height);
    ASSERT_EQ(read_checkpoint(path, key(), kSamples, g, done), "");
    EXPECT_EQ(done, (std::vector<bool>{true, false, false, false, false, false}));
    expect_tile(g, 1, false);
}

TEST(Checkpoint, AnotherJobsFileIsRefused) {
    const std::string dir = test::make_temp_dir();
    const std::string path = write(dir + "/ck", {0});
    Film f(kGrid.width, kGrid.height);
    std::vector<bool> done;
    EXPECT_NE(read_checkpoint(path, key(8), kSamples, f, done).find("another scene, textures or meshes"),
              std::string::npos);
    EXPECT_NE(read_checkpoint(path, key(7, TileGrid{20, 10, 16}), kSamples, f, done).find("tiles of 8"),
              std::string::npos);
    // The setting that differs is named, with both values.
    EXPECT_NE(read_checkpoint(path, key(7, kGrid, "width=20;height=10;spp=4;time=0.5;tile=8;"), kSamples, f, done)
                  .find("was made with --time 0, not 0.5"),
              std::string::npos);
    EXPECT_NE(read_checkpoint(path, key(7, kGrid, "width=20;height=10;spp=8;time=0;tile=8;"), kSamples, f, done)
                  .find("was made with --spp 4, not 8"),
              std::string::npos);
    std::ofstream(dir + "/text") << "not a checkpoint at all, but long enough to hold a header";
    EXPECT_NE(read_checkpoint(dir + "/text", key(), kSamples, f, done).find("not a whitted checkpoint"),
              std::string::npos);
    EXPECT_NE(read_checkpoint(dir + "/none", key(), kSamples, f, done).find("cannot read"), std::string::npos);
    {  // a damaged header (a byte of its settings text): not read as another job's
        std::fstream io(path, std::ios::in | std::ios::out | std::ios::binary);
        io.seekp(42);
        io.put('#');
    }
    EXPECT_NE(read_checkpoint(path, key(), kSamples, f, done).find("damaged"), std::string::npos);
}

TEST(Checkpoint, ReopeningKeepsTheTilesAlreadyDone) {
    const std::string path = write(test::make_temp_dir() + "/ck", {4});
    Film f(kGrid.width, kGrid.height);
    std::vector<bool> done;
    ASSERT_EQ(read_checkpoint(path, key(), kSamples, f, done), "");
    {
        CheckpointWriter w;  // a resumed job starts the file afresh with what it has
        ASSERT_EQ(w.open(path, key(), {{&f, done, kSamples}}, 100), "");
        const Film full = numbered_film();
        f.copy_from(full, kGrid.tile(2));
        w.append(2, f, kSamples);
    }
    Film g(kGrid.width, kGrid.height);
    ASSERT_EQ(read_checkpoint(path, key(), kSamples, g, done), "");
    EXPECT_EQ(done, (std::vector<bool>{false, false, true, false, true, false}));
    expect_tile(g, 4, true);
    expect_tile(g, 2, true);
}

// One bad record (a flipped byte, its index or its pixels) dropped every good
// record after it. The next record is looked for where the bad one would end, for each size of tile.
TEST(Checkpoint, ABadRecordCostsOnlyItsOwnTile) {
    const std::string dir = test::make_temp_dir();
    // Tiles 0 (8 × 8), 2 (4 × 8), 3 (8 × 2), 5 (4 × 2): every size of record there is.
    const std::vector<int> tiles{0, 2, 3, 5};
    auto record_size = [](int t) { return 4 + 4 + std::size_t(kGrid.pixels(t)) * sizeof(FilmPixel) + 8; };
    const std::size_t header = std::filesystem::file_size(write(dir + "/empty", {}));
    for (int bad : {0, 1, 2}) {  // the record of tiles[bad]
        SCOPED_TRACE(bad);
        const std::string path = write(dir + "/ck" + std::to_string(bad), tiles);
        std::size_t start = header;
        for (int k = 0; k < bad; ++k) start += record_size(tiles[std::size_t(k)]);
        for (const std::size_t offset : {std::size_t(1), std::size_t(37)}) {  // its index; its pixels
            std::fstream io(path, std::ios::in | std::ios::out | std::ios::binary);
            io.seekg(std::streamoff(start + offset));
            const char c = char(io.get());
            io.seekp(std::streamoff(start + offset));
            io.put(char(c ^ 0x55));
            io.close();
            Film f(kGrid.width, kGrid.height);
            std::vector<bool> done;
            ASSERT_EQ(read_checkpoint(path, key(), kSamples, f, done), "");
            std::vector<bool> want(6, false);
            for (int t : tiles) want[std::size_t(t)] = t != tiles[std::size_t(bad)];
            EXPECT_EQ(done, want) << "flipped byte " << offset;
            for (int t = 0; t < kGrid.count(); ++t) expect_tile(f, t, want[std::size_t(t)]);
            io.open(path, std::ios::in | std::ios::out | std::ios::binary);  // undo
            io.seekp(std::streamoff(start + offset));
            io.put(c);
        }
    }
}

// --resume /dev/zero read until memory ran out, a FIFO blocked. A checkpoint
// is read through base/read_file.h: a regular file, no larger than one of this job can be.
TEST(Checkpoint, ResumeReadsOnlyARegularFileOfAPossibleSize) {
    const std::string dir = test::make_temp_dir();
    Film f(kGrid.width, kGrid.height);
    std::vector<bool> done;
    EXPECT_NE(read_checkpoint("/dev/zero", key(), kSamples, f, done).find("it is not a regular file"), std::string::npos);
    ASSERT_EQ(mkfifo((dir + "/fifo").c_str(), 0600), 0);
    EXPECT_NE(read_checkpoint(dir + "/fifo", key(), kSamples, f, done).find("it is not a regular file"), std::string::npos);
    const std::string path = write(dir + "/ck", {0, 1, 2, 3, 4, 5});
    ASSERT_EQ(read_checkpoint(path, key(), kSamples, f, done), "");
    // The largest there is: the header with the longest settings text, every tile twice (a whole
    // pass and the next).
    const std::size_t header = 40 + (std::size_t(1) << 16) + 8;
    const std::size_t records = std::size_t(kGrid.count()) * 16 + std::size_t(kGrid.width * kGrid.height) * 16;
    std::filesystem::resize_file(path, header + 2 * records + 1);
    EXPECT_NE(read_checkpoint(path, key(), kSamples, f, done).find("no checkpoint of this job is as large"),
              std::string::npos);
}

// --checkpoint scene.sc overwrote the scene, --checkpoint good.png -o good.png
// the image. A checkpoint may not be anything the job reads or writes, by any name.
TEST(Checkpoint, MayNotBeWhatTheJobReadsOrWrites) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = test::write_file(dir, "s.sc", "camera [ ]\n");
    const std::string texture = test::write_file(dir, "t.png", "png");
    std::filesystem::create_symlink("s.sc", dir + "/link.sc");
    const std::vector<std::string> inputs{scene, texture};
    const std::string out = dir + "/out.png";
    EXPECT_NE(checkpoint_conflict(scene, out, inputs).find("is '" + scene + "', which the job reads"), std::string::npos);
    EXPECT_NE(checkpoint_conflict(dir + "/link.sc", out, inputs), "");
    EXPECT_NE(checkpoint_conflict(dir + "/./t.png", out, inputs), "");
    EXPECT_NE(checkpoint_conflict(out, out, inputs).find("is the output image"), std::string::npos);  // not there yet
    EXPECT_NE(checkpoint_conflict(dir + "/out.partial.png", out, inputs).find("an interrupted job writes"),
              std::string::npos);
    EXPECT_EQ(checkpoint_conflict(dir + "/ck", out, inputs), "");
}

// whitted renders in passes (1, 2, 4, 8 samples here): a file holds the last whole pass (every
// tile) and the tiles of the pass under way; the resume takes the most whole passes there are.
TEST(Checkpoint, APassRenderGoesOnFromTheMostWholePassesAndTheTilesOfTheNext) {
    const std::string dir = test::make_temp_dir();
    const std::vector<int> ends{1, 2, 4, 8};
    const Film f = numbered_film();
    Film other = numbered_film();
    for (int y = 0; y < kGrid.height; ++y)
        for (int x = 0; x < kGrid.width; ++x) other.at(x, y).weight += 100.0f;
    {
        CheckpointWriter w;
        ASSERT_EQ(w.open(dir + "/ck", key(), {{&f, {}, 2}}, 100), "");  // after the second pass
        w.append(4, other, 4);
        w.append(1, other, 4);
    }
    CheckpointContents contents;
    ASSERT_EQ(read_checkpoint(dir + "/ck", key(), contents), "");
    EXPECT_EQ(contents.tiles_at(2), 6);
    EXPECT_EQ(contents.tiles_at(4), 2);
    PassesResumed r = passes_resumed(contents, kGrid, ends);
    EXPECT_EQ(r.passes, 2);
    EXPECT_EQ(r.next_tiles, 2);
    EXPECT_EQ(r.next_done, (std::vector<bool>{false, true, false, false, true, false}));
    for (int t = 0; t < kGrid.count(); ++t) expect_tile(r.whole, t, true);
    EXPECT_EQ(std::memcmp(&r.next.at(kGrid.tile(4).x0, kGrid.tile(4).y0), &other.at(kGrid.tile(4).x0, kGrid.tile(4).y0),
                          sizeof(FilmPixel)),
              0);
    // The next whole pass replaces the file: its tiles and no others.
    {
        CheckpointWriter w;
        ASSERT_EQ(w.open(dir + "/ck", key(), {{&other, {}, 4}}, 100), "");
    }
    ASSERT_EQ(read_checkpoint(dir + "/ck", key(), contents), "");
    EXPECT_EQ(contents.tiles_at(2), 0);
    r = passes_resumed(contents, kGrid, ends);
    EXPECT_EQ(r.passes, 3);
    EXPECT_EQ(r.next_tiles, 0);
    // whitted-mpi's tiles hold every sample of the job: the render's last pass, or its only one.
    write(dir + "/mpi", {0, 5}, 7);
    ASSERT_EQ(read_checkpoint(dir + "/mpi", key(), contents), "");
    r = passes_resumed(contents, kGrid, {kSamples});
    EXPECT_EQ(r.passes, 0);
    EXPECT_EQ(r.next_tiles, 2);
    r = passes_resumed(contents, kGrid, {1, 2, kSamples});
    EXPECT_EQ(r.passes, 0) << "tiles of the last pass are of no use without the pass before";
    EXPECT_EQ(r.next_tiles, 0);
    write(dir + "/all", {0, 1, 2, 3, 4, 5}, 7);
    ASSERT_EQ(read_checkpoint(dir + "/all", key(), contents), "");
    EXPECT_EQ(passes_resumed(contents, kGrid, {1, 2, kSamples}).passes, 3);
}

// The hash of the inputs covers every byte of the scene and of each texture and mesh file, and
// their names (a texture renamed in the scene is another job).
TEST(Checkpoint, TheInputsHashCoversEveryFileAndName) {
    const TextureFiles none;
    const TextureFiles tex{{"a.png", {1, 2, 3}}};
    const std::uint64_t base = inputs_hash("camera [ ]", tex, none);
    EXPECT_NE(inputs_hash("camera [ ] ", tex, none), base);
    EXPECT_NE(inputs_hash("camera [ ]", TextureFiles{{"a.png", {1, 2, 4}}}, none), base);
    EXPECT_NE(inputs_hash("camera [ ]", TextureFiles{{"b.png", {1, 2, 3}}}, none), base);
    EXPECT_NE(inputs_hash("camera [ ]", none, tex), base) << "a mesh is not a texture";
    EXPECT_EQ(inputs_hash("camera [ ]", TextureFiles{{"a.png", {1, 2, 3}}}, none), base);
}

}  // namespace
}  // namespace whitted

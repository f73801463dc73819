// whitted-mpi's checkpoint: the tiles written come back with the same bytes; a record cut short
// by a kill, or damaged, is dropped (that tile is rendered again); another job's file is refused;
// a good file is replaced only whole.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "checkpoint.h"
#include "support/run_process.h"

namespace whitted::mpi {
namespace {

const TileGrid kGrid{20, 10, 8};  // 3 × 2 tiles, the last column and row cut short

Film numbered_film() {
    Film f(kGrid.width, kGrid.height);
    for (int y = 0; y < kGrid.height; ++y)
        for (int x = 0; x < kGrid.width; ++x) f.at(x, y) = {glm::vec3(x, y, 0.1f * float(x * y)), float(x + 3)};
    return f;
}

std::string write(const std::string& path, const std::vector<int>& tiles, std::uint64_t hash = 7) {
    const Film f = numbered_film();
    CheckpointWriter w;
    std::vector<bool> none(std::size_t(kGrid.count()), false);
    EXPECT_EQ(w.open(path, {hash, kGrid}, f, none, 100), "");
    for (int t : tiles) w.append(t, f);
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
    ASSERT_EQ(read_checkpoint(path, {7, kGrid}, f, done), "");
    EXPECT_EQ(done, (std::vector<bool>{true, false, false, true, false, true}));
    for (int t = 0; t < kGrid.count(); ++t) expect_tile(f, t, done[std::size_t(t)]);
}

TEST(Checkpoint, ARecordCutShortOrDamagedIsDropped) {
    const std::string path = write(test::make_temp_dir() + "/ck", {0, 1, 2});
    const auto size = std::filesystem::file_size(path);
    // Each record: index, the tile's pixels, checksum. Tile 2 is 4 × 8 pixels.
    const std::size_t last = 4 + 4 * 8 * sizeof(FilmPixel) + 8;
    std::filesystem::resize_file(path, size - 1);
    Film f(kGrid.width, kGrid.height);
    std::vector<bool> done;
    ASSERT_EQ(read_checkpoint(path, {7, kGrid}, f, done), "");
    EXPECT_EQ(done, (std::vector<bool>{true, true, false, false, false, false}));
    expect_tile(f, 2, false);

    {  // one flipped byte inside tile 1's pixels
        std::fstream io(path, std::ios::in | std::ios::out | std::ios::binary);
        io.seekp(std::streamoff(size - last - 20));
        io.put('\x55');
    }
    Film g(kGrid.width, kGrid.height);
    ASSERT_EQ(read_checkpoint(path, {7, kGrid}, g, done), "");
    EXPECT_EQ(done, (std::vector<bool>{true, false, false, false, false, false}));
    expect_tile(g, 1, false);
}

TEST(Checkpoint, AnotherJobsFileIsRefused) {
    const std::string dir = test::make_temp_dir();
    const std::string path = write(dir + "/ck", {0});
    Film f(kGrid.width, kGrid.height);
    std::vector<bool> done;
    EXPECT_NE(read_checkpoint(path, {8, kGrid}, f, done).find("another scene"), std::string::npos);
    EXPECT_NE(read_checkpoint(path, {7, TileGrid{20, 10, 16}}, f, done).find("tiles of 8"), std::string::npos);
    std::ofstream(dir + "/text") << "not a checkpoint at all, but long enough to hold a header";
    EXPECT_NE(read_checkpoint(dir + "/text", {7, kGrid}, f, done).find("not a whitted-mpi checkpoint"),
              std::string::npos);
    EXPECT_NE(read_checkpoint(dir + "/none", {7, kGrid}, f, done).find("cannot read"), std::string::npos);
}

TEST(Checkpoint, ReopeningKeepsTheTilesAlreadyDone) {
    const std::string path = write(test::make_temp_dir() + "/ck", {4});
    Film f(kGrid.width, kGrid.height);
    std::vector<bool> done;
    ASSERT_EQ(read_checkpoint(path, {7, kGrid}, f, done), "");
    {
        CheckpointWriter w;  // a resumed job starts the file afresh with what it has
        ASSERT_EQ(w.open(path, {7, kGrid}, f, done, 100), "");
        const Film full = numbered_film();
        f.copy_from(full, kGrid.tile(2));
        w.append(2, f);
    }
    Film g(kGrid.width, kGrid.height);
    ASSERT_EQ(read_checkpoint(path, {7, kGrid}, g, done), "");
    EXPECT_EQ(done, (std::vector<bool>{false, false, true, false, true, false}));
    expect_tile(g, 4, true);
    expect_tile(g, 2, true);
}

}  // namespace
}  // namespace whitted::mpi

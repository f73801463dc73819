// gen_scene: writes a large benchmark scene, a grid of N objects on a ground plane, as a .sc file
// (using instancing: one 10×10 block of objects, placed N/100 times) and optionally the same
// scene for POV-Ray 3.7, so that both renderers see identical geometry, lights and camera.
//
//   gen_scene --count 1000000 -o grid1m.sc [--pov grid1m.pov]
//   gen_scene --count 10000 --flat -o flat10k.sc     # every object written out: a parser benchmark
//
// Objects: the four shapes in turn, each rotated and scaled in its 1×1 cell, matte or mirror.
// The camera looks down at the grid from the south; one point light, one directional light.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace {

constexpr const char* kShapes[] = {"cube", "cylinder", "cone", "sphere"};

struct Cell {
    int shape;
    float x, z, angle;  // position in the block, rotation about (1, 1, 0) in degrees
    float sx, sy, sz;
    bool mirror;
    glm::vec3 colour;
};

// The 100 objects of a block, a fixed pattern (no randomness: the files are reproducible).
std::vector<Cell> block() {
    std::vector<Cell> cells;
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j) {
            const int k = i * 10 + j;
            Cell c;
            c.shape = (i + j) % 4;
            c.x = float(i) + 0.5f;
            c.z = float(j) + 0.5f;
            c.angle = float((k * 37) % 90);
            c.sx = 0.5f + 0.04f * float(k % 7);
            c.sy = 0.5f + 0.05f * float(k % 5);
            c.sz = 0.5f + 0.03f * float(k % 9);
            c.mirror = k % 10 == 3;
            c.colour = glm::vec3(0.3f + 0.07f * float(k % 10), 0.3f + 0.06f * float(k % 11), 0.9f - 0.05f * float(k % 13));
            cells.push_back(c);
        }
    return cells;
}

// The object-to-world matrix of a cell inside its block, in the .sc order translate·rotate·scale.
glm::mat4 cell_matrix(const Cell& c) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), {c.x, 0.5f * c.sy, c.z});
    m = glm::rotate(m, glm::radians(c.angle), glm::normalize(glm::vec3(1, 1, 0)));
    return glm::scale(m, {c.sx, c.sy, c.sz});
}

struct Layout {
    int blocks_x, blocks_z;
    float width() const { return 10.0f * float(blocks_x); }
    float depth() const { return 10.0f * float(blocks_z); }
    glm::vec3 eye() const { return {0.0f, 0.45f * std::max(width(), depth()), 0.5f * depth() + 0.35f * std::max(width(), depth())}; }
    glm::vec3 focus() const { return {0.0f, 0.0f, -0.05f * depth()}; }
    glm::vec3 light() const { return {0.3f * width(), 2.0f * std::max(width(), depth()), 0.4f * depth()}; }
};

void write_sc(std::ostream& out, const Layout& L, const std::vector<Cell>& cells, long count, bool flat) {
    const glm::vec3 e = L.eye(), f = L.focus(), l = L.light();
    out << "# " << count << " objects: a " << 10 * L.blocks_x << " x " << 10 * L.blocks_z
        << " grid, written by bench/gen_scene\n";
    out << "camera [ eye " << e.x << " " << e.y << " " << e.z << "  focus " << f.x << " " << f.y << " " << f.z
        << "  up 0 1 0  angle 50 ]\n";
    out << "background [ color 0.5 0.65 0.85 ]\n";
    out << "light [ type point  position " << l.x << " " << l.y << " " << l.z << "  color 0.8 0.8 0.8 ]\n";
    out << "light [ type directional  direction -0.3 -1 -0.5  color 0.3 0.3 0.3 ]\n";
    out << "light [ ambient 0.2 0.2 0.2 ]\n\n";
    // One object's trans block, its cell moved by (dx, dz).
    auto object = [&](const Cell& c, float dx, float dz) {
        out << "  trans [ translate " << c.x + dx << " " << 0.5f * c.sy << " " << c.z + dz << "  rotate 1 1 0 " << c.angle
            << "  scale " << c.sx << " " << c.sy << " " << c.sz << "\n    object " << kShapes[c.shape] << " [ diffuse "
            << c.colour.x << " " << c.colour.y << " " << c.colour.z << "  ambient 0.2 0.2 0.2  specular 0.4 0.4 0.4  shine 30";
        if (c.mirror) out << "  reflect 0.5 0.5 0.5";
        out << " ] ]\n";
    };
    if (flat) {  // the same objects, each written out in root: text in proportion to the count
        out << "mastersubgraph root [\n";
        for (int bx = 0; bx < L.blocks_x; ++bx)
            for (int bz = 0; bz < L.blocks_z; ++bz)
                for (const Cell& c : cells) object(c, 10 * bx - 0.5f * L.width(), 10 * bz - 0.5f * L.depth());
        out << "]\n";
        return;
    }
    out << "mastersubgraph block [\n";
    for (const Cell& c : cells) object(c, 0, 0);
    out << "]\n\nmastersubgraph root [\n";
    for (int bx = 0; bx < L.blocks_x; ++bx)
        for (int bz = 0; bz < L.blocks_z; ++bz)
            out << "  trans [ translate " << 10 * bx - 0.5f * L.width() << " 0 " << 10 * bz - 0.5f * L.depth()
                << " subgraph block ]\n";
    out << "]\n";
}

// POV-Ray is left-handed: the scene is written in our coordinates and the camera's right vector
// is negated, which is POV-Ray's documented way to render a right-handed scene. Its `angle` is
// the horizontal field of view. Same lights (POV-Ray's point light has no distance falloff, like
// ours with `function 1 0 0`), Phong highlight and mirror reflection; shadows from both lights.
void write_pov(std::ostream& out, const Layout& L, const std::vector<Cell>& cells, long count, float aspect) {
    const glm::vec3 e = L.eye(), f = L.focus(), l = L.light();
    const float hfov = 2.0f * std::atan(std::tan(glm::radians(25.0f)) * aspect);
    out << "// " << count << " objects, the same scene as the .sc written by bench/gen_scene\n";
    out << "#version 3.7;\nglobal_settings { max_trace_level 5 assumed_gamma 1.0 ambient_light rgb 0.2 }\n";
    out << "camera { perspective location <" << e.x << "," << e.y << "," << e.z << "> up y right -x*" << aspect
        << " angle " << glm::degrees(hfov) << " look_at <" << f.x << "," << f.y << "," << f.z << "> }\n";
    out << "background { rgb <0.5,0.65,0.85> }\n";
    out << "light_source { <" << l.x << "," << l.y << "," << l.z << "> rgb 0.8 }\n";
    out << "light_source { <0.3,1,0.5>*1e6 rgb 0.3 parallel point_at <0,0,0> }\n";
    out << "#declare Block = union {\n";
    for (const Cell& c : cells) {
        const glm::mat4 m = cell_matrix(c);
        switch (c.shape) {
            case 0: out << "  box { -0.5, 0.5"; break;
            case 1: out << "  cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5"; break;
            case 2: out << "  cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0"; break;
            default: out << "  sphere { 0, 0.5"; break;
        }
        // POV-Ray's matrix is row-vector: its rows are the images of the axes, then the translation.
        out << " matrix <";
        for (int col = 0; col < 4; ++col)
            for (int row = 0; row < 3; ++row) out << m[col][row] << (col == 3 && row == 2 ? "" : ",");
        out << "> pigment { rgb <" << c.colour.x << "," << c.colour.y << "," << c.colour.z
            << "> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30";
        if (c.mirror) out << " reflection 0.5";
        out << " } }\n";
    }
    out << "}\n";
    for (int bx = 0; bx < L.blocks_x; ++bx)
        for (int bz = 0; bz < L.blocks_z; ++bz)
            out << "object { Block translate <" << 10 * bx - 0.5f * L.width() << ",0," << 10 * bz - 0.5f * L.depth()
                << "> }\n";
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"gen_scene: writes a grid of N objects (N a multiple of 100) as a .sc scene, and optionally as POV-Ray"};
    long count = 10000;
    std::string output, pov;
    bool flat = false;
    float aspect = 4.0f / 3.0f;
    app.add_option("-n,--count", count, "Number of objects (a multiple of 100)")->check(CLI::Range(100L, 100000000L));
    app.add_option("-o,--output", output, "The .sc file to write")->required();
    app.add_flag("--flat", flat, "Write every object out in root instead of instancing one block (a parser benchmark)");
    app.add_option("--pov", pov, "Also write the scene for POV-Ray 3.7 to this file");
    app.add_option("--aspect", aspect, "Image aspect ratio the POV-Ray camera is set up for")->check(CLI::PositiveNumber);
    CLI11_PARSE(app, argc, argv);
    if (count % 100 != 0) {
        std::cerr << "gen_scene: --count must be a multiple of 100\n";
        return 1;
    }
    // Blocks in a near-square rectangle: bz the largest divisor of count/100 up to its square root.
    const long blocks = count / 100;
    long bz = long(std::sqrt(double(blocks)));
    while (blocks % bz != 0) --bz;
    const Layout layout{int(blocks / bz), int(bz)};
    const std::vector<Cell> cells = block();

    std::ofstream sc(output);
    if (!sc) {
        std::cerr << "gen_scene: cannot write " << output << "\n";
        return 1;
    }
    write_sc(sc, layout, cells, count, flat);
    if (!pov.empty()) {
        std::ofstream p(pov);
        if (!p) {
            std::cerr << "gen_scene: cannot write " << pov << "\n";
            return 1;
        }
        write_pov(p, layout, cells, count, aspect);
    }
    return 0;
}

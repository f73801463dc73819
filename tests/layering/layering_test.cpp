// The folders of src/ as floors: each folder's CMakeLists.txt names the folders it may use
// (whitted_library(NAME USES …)), the build gives it only their headers, and this test checks what
// the build cannot: that the floors form no cycle (CMake accepts libraries that link each other),
// that every include goes to a folder the library may use, and that no two folders include each
// other.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using Graph = std::map<std::string, std::set<std::string>>;

std::string read(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

const fs::path kSrc = fs::path(WHITTED_SOURCE_DIR) / "src";

// Folder → the folders its CMakeLists.txt says it uses.
Graph declared_uses() {
    Graph uses;
    const std::regex call(R"(whitted_library\(\s*(\w+)([^)]*)\))");
    for (const auto& entry : fs::directory_iterator(kSrc)) {
        if (!entry.is_directory()) continue;
        const std::string folder = entry.path().filename();
        const std::string text = read(entry.path() / "CMakeLists.txt");
        std::smatch m;
        if (!std::regex_search(text, m, call)) {
            ADD_FAILURE() << "src/" << folder << "/CMakeLists.txt declares no whitted_library";
            continue;
        }
        EXPECT_EQ(m[1].str(), folder) << "the library of src/" << folder << " is named after another folder";
        std::istringstream args(m[2].str());
        std::string word;
        bool in_uses = false;
        uses[folder];
        while (args >> word) {
            if (word == "USES") in_uses = true;
            else if (word == "PRIVATE_LIBS") in_uses = false;
            else if (in_uses) uses[folder].insert(word);
        }
    }
    return uses;
}

// Folder → the folders its files include ("folder/file.h").
Graph actual_includes() {
    Graph includes;
    const std::regex include(R"(#include\s+"(\w+)/[^"]+")");
    for (const auto& entry : fs::recursive_directory_iterator(kSrc)) {
        const std::string ext = entry.path().extension();
        if (ext != ".h" && ext != ".cpp") continue;
        const std::string folder = fs::relative(entry.path(), kSrc).begin()->string();
        const std::string text = read(entry.path());
        for (std::sregex_iterator it(text.begin(), text.end(), include), end; it != end; ++it)
            if ((*it)[1] != folder) includes[folder].insert((*it)[1]);
    }
    return includes;
}

std::set<std::string> reachable(const Graph& g, const std::string& from) {
    std::set<std::string> seen;
    std::function<void(const std::string&)> visit = [&](const std::string& f) {
        const auto it = g.find(f);
        if (it == g.end()) return;
        for (const std::string& to : it->second)
            if (seen.insert(to).second) visit(to);
    };
    visit(from);
    return seen;
}

TEST(Layering, TheDeclaredFloorsFormNoCycle) {
    const Graph uses = declared_uses();
    ASSERT_GT(uses.size(), 10u) << "the folders of src/ were not found";
    for (const auto& [folder, _] : uses)
        EXPECT_FALSE(reachable(uses, folder).count(folder)) << "src/" << folder << " uses itself through its floors";
}

TEST(Layering, EveryIncludeGoesToAFolderTheLibraryMayUse) {
    const Graph uses = declared_uses(), includes = actual_includes();
    for (const auto& [folder, targets] : includes) {
        const std::set<std::string> allowed = reachable(uses, folder);
        for (const std::string& to : targets)
            EXPECT_TRUE(allowed.count(to)) << "src/" << folder << " includes src/" << to
                                           << "/, which its CMakeLists.txt does not let it use";
    }
}

TEST(Layering, NoTwoFoldersIncludeEachOther) {
    const Graph includes = actual_includes();
    for (const auto& [folder, targets] : includes)
        for (const std::string& to : targets) {
            const auto back = includes.find(to);
            EXPECT_FALSE(back != includes.end() && back->second.count(folder))
                << "src/" << folder << " and src/" << to << " include each other";
        }
}

}  // namespace

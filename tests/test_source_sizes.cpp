// The library's source files stay small enough to read as one concept each: no .hpp or .cpp over
// 700 lines. The library is every folder of the source but tests/, bench/, fuzz/ and examples/;
// build folders (those holding a CMakeCache.txt) and hidden ones are not sources.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

namespace {

constexpr std::size_t kMaxLines = 700;

/// Lines as `wc -l` counts them: the newlines.
std::size_t line_count(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return static_cast<std::size_t>(
        std::count(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>(), '\n'));
}

}  // namespace

TEST_CASE("sources: no library .hpp or .cpp file is over 700 lines", "[sources]") {
    namespace fs = std::filesystem;
    const fs::path top = PRIDE_SOURCE_DIR;
    const std::set<std::string> exempt{"tests", "bench", "fuzz", "examples"};
    std::vector<std::string> over;
    std::size_t checked = 0;
    for (auto it = fs::recursive_directory_iterator(top); it != fs::recursive_directory_iterator(); ++it) {
        const fs::path& path = it->path();
        const std::string name = path.filename().string();
        if (it->is_directory()) {
            if ((it.depth() == 0 && exempt.count(name)) || name.starts_with('.') || fs::exists(path / "CMakeCache.txt"))
                it.disable_recursion_pending();
            continue;
        }
        if (!it->is_regular_file() || (path.extension() != ".hpp" && path.extension() != ".cpp")) continue;
        ++checked;
        if (const std::size_t n = line_count(path); n > kMaxLines)
            over.push_back(fs::relative(path, top).string() + ": " + std::to_string(n) + " lines");
    }
    std::string list;
    for (const auto& o : over) list += "\n  " + o;
    INFO("over " << kMaxLines << " lines (split each along its concepts):" << list);
    CHECK(over.empty());
    CHECK(checked > 300);  // the walk did find the library
}

#include "experiment/report/published_files.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "experiment/storage/digest.hpp"
#include "experiment/storage/writer.hpp"
#include "framework/error.hpp"

namespace pride::report::published_files {

namespace fs = std::filesystem;

std::string trim(const std::string& s) {
    const auto a = s.find_first_not_of(" \t\r\n");
    if (a == std::string::npos) return "";
    const auto b = s.find_last_not_of(" \t\r\n");
    return s.substr(a, b - a + 1);
}

std::optional<double> number(const std::string& token) {
    if (token.empty()) return std::nullopt;
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(token.c_str(), &end);
    if (end != token.c_str() + token.size() || errno == ERANGE) return std::nullopt;
    return v;
}

std::optional<std::int64_t> count(const std::string& token, std::int64_t min) {
    const auto v = number(token);
    if (!v || !std::isfinite(*v) || *v != std::floor(*v) || *v < static_cast<double>(min) || *v > 9e15)
        return std::nullopt;
    return static_cast<std::int64_t>(*v);
}

std::vector<std::string> read_lines(const fs::path& file, const std::string& what) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec))
        throw InputError(file.string(), fs::exists(file, ec) ? "not a regular file" : "no such file (" + what + ")");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(file.string(), "cannot read the file");
    std::vector<std::string> lines;
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(line);
    }
    return lines;
}

std::string folder_sha256(const fs::path& folder) {
    std::vector<fs::path> files;
    for (const auto& e : fs::recursive_directory_iterator(folder))
        if (e.is_regular_file()) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    storage::Sha256 h;
    for (const auto& f : files) {
        std::ifstream in(f, std::ios::binary);
        std::ostringstream content;
        content << in.rdbuf();
        h.field(fs::relative(f, folder).generic_string()).field(content.str());
    }
    return h.hex();
}

void check_options(const PublishedImportOptions& options) {
    require(!options.name.empty() && options.name.find_first_of("\n\r\t") == std::string::npos, "--name",
            "give the published algorithm a name (one line), e.g. DIRECT");
    require(!options.citation.empty(), "--citation", "say whose runs these are and where they were published");
}

std::string folder_name(const std::string& folder) {
    fs::path named = fs::absolute(folder).lexically_normal();
    if (!named.has_filename()) named = named.parent_path();  // "DIRECT/"
    return named.filename().string();
}

storage::ImportSummary add_to_store(const std::string& store, const storage::PublishedSet& set,
                                    const std::vector<double>& precisions, const std::string& precisions_json) {
    std::error_code ec;
    const bool existed = fs::exists(store, ec);
    try {
        storage::Writer writer(store);
        return writer.import_published(set, precisions, precisions_json);
    } catch (...) {
        if (!existed)  // a store made for this import and left empty: removed with SQLite's files
            for (const char* suffix : {"", "-wal", "-shm", "-journal"}) fs::remove(store + suffix, ec);
        throw;
    }
}

}  // namespace pride::report::published_files

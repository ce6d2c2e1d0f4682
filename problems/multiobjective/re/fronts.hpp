#pragma once
// The RE problems' approximated Pareto fronts and their ideal and nadir points, as the suite
// publishes them (GitHub ryojitanabe/reproblems: approximated_Pareto_fronts/reference_points_RE*.dat,
// ideal_nadir_points/{ideal,nadir}_point_RE*.dat; $PRIDE_DATA/re-fronts holds them, the ideal and
// nadir points under ideal_nadir/). The fronts are those of the fixed RE21, RE25 and RE42 (re.hpp);
// the files named bug_* are the old versions' and are not read. The suite publishes no front of a
// CRE problem.
//
//   Matrix read_re_front(folder, name)        M rows, one column per point of folder/reference_points_REnn.dat
//   std::vector<double> read_re_ideal(folder, name)   folder/ideal_nadir/ideal_point_REnn.dat
//   std::vector<double> read_re_nadir(folder, name)   folder/ideal_nadir/nadir_point_REnn.dat
//
// A file holds one point per line, its M values separated by spaces (or tabs); blank lines are
// skipped. InputError naming the file and line for a line without M numbers, a value that is not a
// finite number (at its column; the text itself is never shown), an empty file, or a file beyond kMaxFrontFileBytes
// (checked before it is read) or kMaxReFrontValues values (checked before the matrix is allocated).
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "framework/error.hpp"
#include "framework/number.hpp"
#include "framework/problem.hpp"
#include "framework/read_file.hpp"
#include "problems/multiobjective/re/re.hpp"

namespace pride::multiobjective::re {

/// The largest file read (the largest published front, RE91's, is 0.4 MiB).
inline constexpr std::size_t kMaxFrontFileBytes = std::size_t{64} << 20;
/// The most values of a front (M x points).
inline constexpr std::size_t kMaxReFrontValues = std::size_t{1} << 24;

namespace detail {

/// "RE21" for "re21"; InputError for a name outside the suite or a CRE name (no published front).
inline std::string file_stem(std::string_view name, const CatalogEntry*& entry) {
    entry = find_problem(name);
    if (entry == nullptr)
        throw InputError("problem", "unknown RE problem '" + std::string(name) + "' (known: " + problem_names() + ")");
    if (entry->constraints > 0)
        throw InputError(std::string(name), "the suite publishes no Pareto front of a CRE problem");
    std::string stem(name);
    for (char& ch : stem)
        if (ch >= 'a' && ch <= 'z') ch = static_cast<char>(ch - 'a' + 'A');
    return stem;
}

/// The rows of numbers of `path`, each of exactly `m` values, in file order, as one flat vector.
inline std::vector<double> read_rows(const std::filesystem::path& path, std::size_t m, std::size_t max_rows) {
    const std::string file = path.string();
    const std::string text = read_capped_file(file, kMaxFrontFileBytes, "RE front");
    // Count the non-blank lines first: the size is checked before anything is allocated for it.
    std::size_t lines = 0;
    {
        std::size_t start = 0;
        while (start < text.size()) {
            std::size_t end = text.find('\n', start);
            if (end == std::string::npos) end = text.size();
            if (text.find_first_not_of(" \t\r", start) < end) ++lines;
            start = end + 1;
        }
    }
    require(lines > 0, file, "no points");
    require(lines <= max_rows, file,
            "too many lines: " + std::to_string(lines) + " of M = " + std::to_string(m) + " values, at most " +
                std::to_string(max_rows) + " read");
    std::vector<double> values;
    values.reserve(lines * m);
    std::size_t start = 0, line_number = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        ++line_number;
        const std::string_view line(text.data() + start, end - start);
        start = end + 1;
        const std::string where = file + ":" + std::to_string(line_number);
        std::size_t count = 0, i = 0;
        while (true) {
            while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
            if (i == line.size()) break;
            std::size_t j = i;
            while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
            const std::string_view token = line.substr(i, j - i);
            double v = 0.0;
            const NumberText what = parse_decimal(token, v);
            // Where, never the text: a file named in the wrong place is not shown.
            if (what != NumberText::ok)
                throw InputError(where + ":" + std::to_string(i + 1),
                                 what == NumberText::too_large
                                     ? "a number beyond the largest finite number (a damaged front file)"
                                     : "expected a finite number (the file is not an RE front)");
            if (++count > m) break;
            values.push_back(v);
            i = j;
        }
        if (count == 0) continue;
        require(count == m, where,
                "expected " + std::to_string(m) + " values (the problem's M), got " +
                    (count > m ? "more" : std::to_string(count)));
    }
    return values;
}

}  // namespace detail

/// The approximated Pareto front of RE problem `name` ("re21" ... "re91"): objectives() rows, one
/// column per point, in the file's order.
inline Matrix read_re_front(const std::filesystem::path& folder, std::string_view name) {
    const CatalogEntry* e = nullptr;
    const std::string stem = detail::file_stem(name, e);
    const std::size_t m = e->objectives;
    const std::vector<double> v =
        detail::read_rows(folder / ("reference_points_" + stem + ".dat"), m, kMaxReFrontValues / m);
    const auto points = static_cast<Eigen::Index>(v.size() / m);
    Matrix out(static_cast<Eigen::Index>(m), points);
    for (Eigen::Index j = 0; j < points; ++j)
        for (std::size_t i = 0; i < m; ++i)
            out(static_cast<Eigen::Index>(i), j) = v[static_cast<std::size_t>(j) * m + i];
    return out;
}

namespace detail {
inline std::vector<double> read_point(const std::filesystem::path& folder, std::string_view name, const char* kind) {
    const CatalogEntry* e = nullptr;
    const std::string stem = file_stem(name, e);
    const std::filesystem::path path = folder / "ideal_nadir" / (std::string(kind) + "_point_" + stem + ".dat");
    return read_rows(path, e->objectives, 1);
}
}  // namespace detail

/// The ideal point of RE problem `name` as the suite publishes it (folder/ideal_nadir/ideal_point_REnn.dat).
inline std::vector<double> read_re_ideal(const std::filesystem::path& folder, std::string_view name) {
    return detail::read_point(folder, name, "ideal");
}
/// The nadir point (folder/ideal_nadir/nadir_point_REnn.dat).
inline std::vector<double> read_re_nadir(const std::filesystem::path& folder, std::string_view name) {
    return detail::read_point(folder, name, "nadir");
}

}  // namespace pride::multiobjective::re

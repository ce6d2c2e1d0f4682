#pragma once
// The HTML report's page as it is built (report_page.cpp), shared with the files that draw some
// of its figures (front_figures.cpp): its HTML so far, its figure files and each algorithm's
// colour. Internal to experiment/html/.
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "engine/specs.hpp"
#include "experiment/html/colour.hpp"
#include "experiment/html/figure.hpp"
#include "experiment/html/page_store.hpp"
#include "experiment/storage/file_name.hpp"
#include "framework/error.hpp"
#include "framework/output_files.hpp"
#include "problems/grid/map.hpp"

namespace pride::html {

inline std::string escape(std::string_view s) {
    std::string out;
    for (const char c : s) switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&#39;";
                break;
            default:
                out += c;
        }
    return out;
}

/// For reading, as the markdown report: 6 significant digits.
inline std::string num(double v) {
    if (std::isnan(v)) return "nan";
    return std::isfinite(v) ? fmt::format("{:.6g}", v) : (v > 0 ? "inf" : "-inf");
}

/// The page as it is built: its HTML, and its figures written into `files` under `folder`.
struct Page {
    OutputFiles* files = nullptr;
    std::filesystem::path folder;
    std::map<std::string, std::string> names;  // problem id -> its file name, no two alike
    std::string html;
    std::string notes;  // of the current problem: under its figures
    std::size_t figures = 0;
    std::map<std::string, std::size_t> algorithms;  // each algorithm's colour and dash, by index

    Rgb colour(const std::string& algorithm) const { return series_colour(algorithms.at(algorithm)); }
    int dash(const std::string& algorithm) const { return static_cast<int>(algorithms.at(algorithm) % 4); }

    /// The figure file of a problem (or an ECDF group): "x/y" and "x_y" get files of their own.
    std::string file(const std::string& kind, const std::string& id) const {
        const auto it = names.find(id);
        return kind + "-" + (it != names.end() ? it->second : storage::file_name(id)) + ".svg";
    }
    OutputFiles::File& create(const std::string& name) { return files->create(folder / name); }
    /// Writes the figure and puts it on the page with its caption (HTML).
    void add(const Figure& f, const std::string& name, const std::string& alt, const std::string& caption) {
        f.write(create(name));
        put(name, alt, caption);
    }
    void put(const std::string& name, const std::string& alt, const std::string& caption) {
        ++figures;
        // Lazily: a campaign's page may hold hundreds of figures; a browser fetches those near the view.
        html +=
            fmt::format("<figure><img src=\"{}\" alt=\"{}\" loading=\"lazy\"><figcaption>{}</figcaption></figure>\n",
                        escape(name), escape(alt), caption);
    }
};

/// The map of a grid problem for its pictures of paths, or null with a note on the page saying
/// why there is none (`info` null or its map given in code, or a map file that cannot be read).
inline std::shared_ptr<const grid::GridMap> picture_map(Page& page, const GridProblemInfo* info) {
    if (!info || info->map.empty()) {
        page.notes += "<p class=\"note\">The map was given in code, not as a file: no picture of the paths.</p>\n";
        return nullptr;
    }
    try {
        grid::MapReadOptions read;
        read.unknown_free = info->unknown_free;
        read.named_in_file = true;  // the store names it: never standard input
        return engine::load_map(info->map, info->inflate, read);
    } catch (const InputError& e) {
        page.notes += "<p class=\"note\">No picture of the paths: " + escape(e.what()) + "</p>\n";
        return nullptr;
    }
}

}  // namespace pride::html

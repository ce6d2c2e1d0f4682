#pragma once
// What the imports of published runs share (`pride import`: COCO's data sets, coco_import.hpp; the
// CEC 2017 entrants' files, cec2017_import.hpp; IOHprofiler files, ioh_import.hpp): the options naming the runs, the
// reading of text files and numbers, the SHA-256 of a folder, and the one transaction that adds a set to a store.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "experiment/storage/published.hpp"

namespace pride::report {

struct PublishedImportOptions {
    std::string name;      // the published algorithm: stored as "published:NAME"
    std::string citation;  // who published the runs, where
    // The source as recorded: by default the folder's name and the SHA-256 of its files (each
    // file's path relative to the folder and content, in order of path); Python gives an
    // archive's name and its own SHA-256 instead.
    std::optional<std::string> source, sha256;
};

namespace published_files {

/// `s` without leading and trailing blanks (spaces, tabs, CR, LF).
std::string trim(const std::string& s);

/// A whole token as a number (C's strtod: COCO's 2009 files and CEC 2017's IDEbestNsize write
/// exponents as "e+001"), or none.
std::optional<double> number(const std::string& token);

/// A whole token as a count of at least `min` (written as an integer or, as some loggers do, as a
/// number with an exponent), or none.
std::optional<std::int64_t> count(const std::string& token, std::int64_t min);

/// The lines of `file`, a trailing CR dropped; InputError naming the file when it is missing (`what`
/// says what it was wanted as), not a regular file or unreadable.
std::vector<std::string> read_lines(const std::filesystem::path& file, const std::string& what);

/// The SHA-256 of a folder's files: each one's path relative to it and its content, by path.
std::string folder_sha256(const std::filesystem::path& folder);

/// InputError naming --name or --citation when either is empty (or the name is not one line).
void check_options(const PublishedImportOptions& options);

/// The name a folder is recorded by: its last component ("DIRECT/" included).
std::string folder_name(const std::string& folder);

/// `set` added to the store at `store` (created when absent) in one transaction:
/// storage::Writer::import_published, its refusals included; a store made for the import is
/// removed when it fails.
storage::ImportSummary add_to_store(const std::string& store, const storage::PublishedSet& set,
                                    const std::vector<double>& precisions, const std::string& precisions_json);

}  // namespace published_files
}  // namespace pride::report

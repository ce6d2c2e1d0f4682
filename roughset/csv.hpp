#pragma once
// Decision tables from CSV files (RFC 4180): the header names the attributes, the last column is
// the decision, values are arbitrary text coded per column in order of first appearance.
#include <string>
#include <string_view>

#include "roughset/decision_table.hpp"

namespace pride::roughset {

/// Quoted fields with "" escapes, CRLF or LF line ends, a UTF-8 BOM, blanks around unquoted fields
/// (trimmed) and blank lines (skipped) are accepted. InputError "SOURCE:LINE:COL: ..." for an empty
/// file, fewer than 2 columns, a duplicate or empty column name, a row with the wrong number of
/// fields, an empty value, an unterminated quote, or no data rows.
DecisionTable parse_csv(std::string_view text, const std::string& source_name);

/// parse_csv on a file's content; InputError "PATH: cannot open ..." when it cannot be read.
DecisionTable read_csv(const std::string& path);

}  // namespace pride::roughset

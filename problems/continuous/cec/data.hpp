#pragma once
// The official data of the CEC suites (shift vectors, rotation matrices, shuffle permutations), read
// from the official code's `input_data` folder. pride does not ship that folder (its files come
// only with the official code: P-N-Suganthan/CEC2017-BoundContrained, CEC17_fast_pow-C++.zip, and
// P-N-Suganthan/2022-SO-BO, CEC2022.zip); the user names it once, by set_data_directory() or the
// environment (PRIDE_CEC2017_DATA, PRIDE_CEC2022_DATA; unset, $PRIDE_DATA/cec2017/input_data and
// $PRIDE_DATA/cec2022/input_data, where they are). Each file is parsed once per process and
// per folder, when a function is made (outside the clock of its evaluations), and kept.
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace pride::continuous::cec {

enum class Suite { y2017, y2022 };

/// "cec2017", "cec2022".
std::string_view suite_name(Suite suite) noexcept;
/// "PRIDE_CEC2017_DATA", "PRIDE_CEC2022_DATA".
std::string_view data_variable(Suite suite) noexcept;

/// Reads `suite`'s files from `directory` from now on in this process (over the environment
/// variable). An empty string goes back to the environment.
void set_data_directory(Suite suite, std::string directory);

/// The folder the environment names: data_variable(suite)'s value; when that variable is unset (not
/// when it is empty), $PRIDE_DATA/cec2017/input_data (cec2022's for 2022) where that folder
/// exists. Empty when neither.
std::string environment_directory(Suite suite);

/// The folder in use: set_data_directory()'s, else environment_directory()'s. InputError naming
/// `problem` and telling where the data comes from when neither gives one.
std::string data_directory(Suite suite, std::string_view problem);

/// What one function in one dimension reads, in the official loader's layout.
struct Data {
    std::size_t dim = 0;
    std::size_t components = 1;  // rows of `shift`, matrices of `rotation` (compositions: > 1)
    std::vector<double> shift;   // components x dim, row-major (o_i = row i)
    // components matrices of dim x dim, stacked; by rows as in the file, or by columns (the file's
    // transpose) from dimension kRotateByColumns on, where summing columns as vectors is faster
    // (kernel.cpp: rotate; either way in the official code's order).
    std::vector<double> rotation;
    std::vector<int> shuffle;  // 0-based: the official 1-based permutation minus 1 (empty: none)
};

/// From this dimension on, rotations are stored and computed by columns (Data::rotation).
inline constexpr std::size_t kRotateByColumns = 40;

/// What a function needs from the files: `components` shift rows and matrices, `shuffles`
/// permutations of dim (0: no shuffle file).
struct Needs {
    std::size_t components = 1;
    std::size_t shuffles = 0;
};

/// The data of `suite`'s function `function` in dimension `dim`, read from data_directory() once
/// per process and folder. InputError naming the file when it is missing, too short, holds
/// something other than a finite number, or a shuffle that is not a permutation of 1..dim.
std::shared_ptr<const Data> load(Suite suite, int function, std::size_t dim, Needs needs);

/// Parsing, apart from the files (what load() applies to each; tested on its own). `name` is what
/// errors name. read_numbers: the first `count` numbers of `text`, whatever the lines.
/// read_rows: the first `per_row` numbers of each of the first `rows` lines holding numbers, as
/// the official loader does (it reads a row, then skips the rest of its line).
std::vector<double> read_numbers(std::string_view text, std::size_t count, const std::string& name);
std::vector<double> read_rows(std::string_view text, std::size_t rows, std::size_t per_row, const std::string& name);
std::vector<int> read_permutations(std::string_view text, std::size_t count, std::size_t dim, const std::string& name);

}  // namespace pride::continuous::cec

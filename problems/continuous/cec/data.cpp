#include "problems/continuous/cec/data.hpp"

#include <Eigen/LU>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>
#include <tuple>

#include "framework/error.hpp"
#include "framework/read_file.hpp"

namespace pride::continuous::cec {

namespace {

// The largest official file (M_30_D100.txt, ten 100 x 100 matrices) has 2.5 MB.
constexpr std::size_t kMaxFileBytes = std::size_t{64} << 20;

struct State {
    std::mutex mutex;
    std::string directory[2];  // set_data_directory(), per suite
    std::map<std::tuple<int, std::string, int, std::size_t>, std::shared_ptr<const Data>> cache;
};

State& state() {
    static State s;
    return s;
}

int index(Suite suite) noexcept {
    return suite == Suite::y2017 ? 0 : 1;
}

bool space(char c) noexcept {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

/// A cursor over a file's text: numbers separated by white space, as fscanf reads them.
class Tokens {
  public:
    Tokens(std::string_view text, const std::string& name) : text_(text), name_(name) {}

    /// The next number; InputError naming the file and line when there is none or it is not one.
    double number(std::size_t wanted) {
        const std::string_view token = next(wanted);
        double v = 0;
        const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
        if (ec != std::errc() || end != token.data() + token.size() || !std::isfinite(v))
            throw InputError(where(), "expected a finite number (the file is not CEC data)");
        return v;
    }
    long long integer(std::size_t wanted) {
        const std::string_view token = next(wanted);
        long long v = 0;
        const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
        if (ec != std::errc() || end != token.data() + token.size())
            throw InputError(where(), "expected an integer (the file is not CEC data)");
        return v;
    }
    /// What fscanf's "%*[^\n]%*c" does after a row: the rest of the current line is skipped.
    void skip_line() {
        while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
        if (pos_ < text_.size()) {
            ++pos_;
            ++line_;
        }
    }
    std::string where() const { return name_ + ":" + std::to_string(line_); }
    /// Nothing but white space left.
    bool at_end() const {
        std::size_t p = pos_;
        while (p < text_.size() && space(text_[p])) ++p;
        return p == text_.size();
    }

  private:
    std::string_view next(std::size_t wanted) {
        while (pos_ < text_.size() && space(text_[pos_])) {
            if (text_[pos_] == '\n') ++line_;
            ++pos_;
        }
        if (pos_ == text_.size())
            throw InputError(name_, "holds " + std::to_string(read_) + " numbers where " + std::to_string(wanted) +
                                        " are needed (a truncated or wrong file)");
        const std::size_t start = pos_;
        while (pos_ < text_.size() && !space(text_[pos_])) ++pos_;
        ++read_;
        return text_.substr(start, pos_ - start);
    }

    std::string_view text_;
    const std::string& name_;
    std::size_t pos_ = 0;
    std::size_t line_ = 1;
    std::size_t read_ = 0;
};

std::string read(const std::string& directory, const std::string& file) {
    const std::string path = directory + "/" + file;
    return read_capped_file(path, kMaxFileBytes, "CEC data");
}

// What the data may hold, so that a damaged or hostile file cannot make every value infinite or
// the function lose a dimension: the official files hold shifts within [-80, 80] and matrices of
// full rank with entries within [-3, 3]. A shift must lie in the suites' search box [-100, 100]
// (an optimum outside it is no CEC problem); a matrix's entries within [-1000, 1000] and the
// matrix of full rank (a singular one, an all-zero one say, is refused, not run).
constexpr double kSearchBound = 100.0, kMaxMatrixEntry = 1000.0;

void check_shifts(const std::vector<double>& shift, const std::string& name) {
    for (std::size_t i = 0; i < shift.size(); ++i)
        if (std::fabs(shift[i]) > kSearchBound)
            throw InputError(name, "shift value " + std::to_string(i + 1) +
                                       " lies outside the search box [-100, 100] (a damaged file)");
}

void check_matrices(const std::vector<double>& rows, std::size_t count, std::size_t dim, const std::string& name) {
    for (std::size_t c = 0; c < count; ++c) {
        const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> m(
            rows.data() + c * dim * dim, static_cast<Eigen::Index>(dim), static_cast<Eigen::Index>(dim));
        const std::string which = "matrix " + std::to_string(c + 1) + " of " + std::to_string(count);
        if (m.cwiseAbs().maxCoeff() > kMaxMatrixEntry)
            throw InputError(name, which + " has an entry outside [-1000, 1000] (a damaged file)");
        const Eigen::FullPivLU<Eigen::MatrixXd> lu(m);
        if (lu.rank() < static_cast<Eigen::Index>(dim))
            throw InputError(name, which + " is singular (rank " + std::to_string(lu.rank()) + " of " +
                                       std::to_string(dim) + "): a damaged file");
    }
}

}  // namespace

std::string_view suite_name(Suite suite) noexcept {
    return suite == Suite::y2017 ? "cec2017" : "cec2022";
}

std::string_view data_variable(Suite suite) noexcept {
    return suite == Suite::y2017 ? "PRIDE_CEC2017_DATA" : "PRIDE_CEC2022_DATA";
}

void set_data_directory(Suite suite, std::string directory) {
    State& s = state();
    const std::lock_guard lock(s.mutex);
    s.directory[index(suite)] = std::move(directory);
}

std::string data_directory(Suite suite, std::string_view problem) {
    {
        State& s = state();
        const std::lock_guard lock(s.mutex);
        if (!s.directory[index(suite)].empty()) return s.directory[index(suite)];
    }
    std::string directory = environment_directory(suite);
    if (!directory.empty()) return directory;
    const bool y2017 = suite == Suite::y2017;
    throw InputError(std::string(problem),
                     "needs the official " + std::string(suite_name(suite)) + " data, which pride does not ship: set " +
                         std::string(data_variable(suite)) +
                         " to the input_data folder of the official code (github.com/P-N-Suganthan/" +
                         (y2017 ? "CEC2017-BoundContrained, CEC17_fast_pow-C++.zip" : "2022-SO-BO, CEC2022.zip") +
                         "), or leave it unset and have that folder at $PRIDE_DATA/" + std::string(suite_name(suite)) +
                         "/input_data");
}

std::string environment_directory(Suite suite) {
    const std::string variable(data_variable(suite));
    if (const char* value = std::getenv(variable.c_str())) return value;  // empty: no data, by choice
    const char* shared = std::getenv("PRIDE_DATA");
    if (!shared || !*shared) return "";
    const std::filesystem::path folder = std::filesystem::path(shared) / suite_name(suite) / "input_data";
    std::error_code ec;
    return std::filesystem::is_directory(folder, ec) ? folder.string() : "";
}

std::vector<double> read_numbers(std::string_view text, std::size_t count, const std::string& name) {
    Tokens tokens(text, name);
    std::vector<double> out(count);
    for (double& v : out) v = tokens.number(count);
    return out;
}

std::vector<double> read_rows(std::string_view text, std::size_t rows, std::size_t per_row, const std::string& name) {
    Tokens tokens(text, name);
    std::vector<double> out(rows * per_row);
    for (std::size_t r = 0; r < rows; ++r) {
        if (tokens.at_end())
            throw InputError(name, "holds " + std::to_string(r) + " rows of numbers where " + std::to_string(rows) +
                                       " are needed (a truncated or wrong file)");
        for (std::size_t j = 0; j < per_row; ++j) out[r * per_row + j] = tokens.number(rows * per_row);
        if (r + 1 < rows) tokens.skip_line();
    }
    return out;
}

std::vector<int> read_permutations(std::string_view text, std::size_t count, std::size_t dim, const std::string& name) {
    Tokens tokens(text, name);
    std::vector<int> out(count * dim);
    for (std::size_t p = 0; p < count; ++p) {
        std::vector<bool> seen(dim, false);
        for (std::size_t j = 0; j < dim; ++j) {
            const long long v = tokens.integer(count * dim);
            if (v < 1 || v > static_cast<long long>(dim) || seen[static_cast<std::size_t>(v - 1)])
                throw InputError(tokens.where(), "entry " + std::to_string(v) + " breaks a permutation of 1.." +
                                                     std::to_string(dim) + " (a damaged shuffle file)");
            seen[static_cast<std::size_t>(v - 1)] = true;
            out[p * dim + j] = static_cast<int>(v - 1);
        }
    }
    return out;
}

std::shared_ptr<const Data> load(Suite suite, int function, std::size_t dim, Needs needs) {
    const std::string problem = std::string(suite_name(suite)) + "-f" + std::to_string(function);
    const std::string directory = data_directory(suite, problem);
    State& s = state();
    const auto key = std::make_tuple(index(suite), directory, function, dim);
    // One lock over the parse: two threads making the same function parse it once.
    const std::lock_guard lock(s.mutex);
    if (const auto it = s.cache.find(key); it != s.cache.end()) return it->second;

    const std::string f = std::to_string(function), d = std::to_string(dim);
    auto data = std::make_shared<Data>();
    data->dim = dim;
    data->components = needs.components;
    const std::string m_file = "M_" + f + "_D" + d + ".txt";
    const std::vector<double> by_rows =
        read_numbers(read(directory, m_file), needs.components * dim * dim, directory + "/" + m_file);
    if (dim < kRotateByColumns) {
        data->rotation = by_rows;
    } else {
        data->rotation.resize(by_rows.size());
        for (std::size_t c = 0; c < needs.components; ++c)
            for (std::size_t i = 0; i < dim; ++i)
                for (std::size_t j = 0; j < dim; ++j)
                    data->rotation[c * dim * dim + j * dim + i] = by_rows[c * dim * dim + i * dim + j];
    }
    check_matrices(by_rows, needs.components, dim, directory + "/" + m_file);
    const std::string s_file = "shift_data_" + f + ".txt";
    const std::string shift_text = read(directory, s_file);
    data->shift = needs.components == 1 ? read_numbers(shift_text, dim, directory + "/" + s_file)
                                        : read_rows(shift_text, needs.components, dim, directory + "/" + s_file);
    check_shifts(data->shift, directory + "/" + s_file);
    if (needs.shuffles > 0) {
        const std::string p_file = "shuffle_data_" + f + "_D" + d + ".txt";
        data->shuffle = read_permutations(read(directory, p_file), needs.shuffles, dim, directory + "/" + p_file);
    }
    s.cache.emplace(key, data);
    return data;
}

}  // namespace pride::continuous::cec

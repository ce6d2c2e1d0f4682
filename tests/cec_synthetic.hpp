#pragma once
// Synthetic input data for the CEC 2017 and CEC 2022 single-objective suites, and the points at
// which tests/test_cec.cpp checks them. The official data may not be kept in this repository, so
// the tests also run on data made here: a complete input_data folder in the official text format
// (M_k_Dd.txt, shift_data_k.txt, shuffle_data_k_Dd.txt), drawn deterministically from an integer
// seed. The reference values of tests/data/cec/ came from the official C code reading such a folder
// (and the official folder), called through a driver that makes its points with point() below;
// tests/data/cec/README.md says how.
//
// Every number is exact in decimal text: a shift entry is k/10^6, a matrix entry k/10^8, a point
// coordinate k/10^6, with integer k, so the official loader (fscanf "%lf") and any correctly
// rounded parser read the same double, the one double(k) / 10^digits gives here (IEEE division
// rounds correctly). The points near the optimum o are o_i + m_i/10^(6+j): one division and one
// addition, no product that a compiler could fuse, so every platform computes the same bits.
//
// The standard library only: the driver of the official code includes this header too.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace pride::test::cec_synthetic {

/// The seed the committed reference values were made with.
inline constexpr std::uint64_t kSeed = 2017'2022;

/// Points per (suite, function, dimension): 0 the optimum o (first shift row); 1-6 o + 10^-j u
/// for j = 1..6 along one direction u in [-1, 1]^D; 7-12 uniform in [-100, 100]^D; 13-14 uniform
/// in [-1000, 1000]^D (outside the box); 15 a corner of the box (each coordinate +-100).
inline constexpr int kPoints = 16;
inline constexpr int kNearFirst = 1, kNearLast = 6;

struct SplitMix64 {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    /// An integer in [lo, hi] (the modulo's tiny bias does not matter here).
    std::int64_t uniform(std::int64_t lo, std::int64_t hi) {
        return lo + static_cast<std::int64_t>(next() % static_cast<std::uint64_t>(hi - lo + 1));
    }
};

/// A generator for one purpose: the seed mixed with the words that name the purpose.
inline SplitMix64 stream(std::uint64_t seed, std::initializer_list<std::uint64_t> words) {
    SplitMix64 g{seed};
    for (const std::uint64_t w : words) g.state = g.next() ^ w;
    g.next();
    return g;
}

inline double power_of_ten(int digits) {
    double p = 1;
    for (int i = 0; i < digits; ++i) p *= 10;  // exact up to 10^22
    return p;
}

/// k / 10^digits, correctly rounded: the double that parsing decimal_text(k, digits) gives.
inline double decimal_value(std::int64_t k, int digits) {
    return static_cast<double>(k) / power_of_ten(digits);
}

/// k / 10^digits as exact decimal text ("-12.345678").
inline std::string decimal_text(std::int64_t k, int digits) {
    const bool negative = k < 0;
    const std::uint64_t a = negative ? 0 - static_cast<std::uint64_t>(k) : static_cast<std::uint64_t>(k);
    std::uint64_t scale = 1;
    for (int i = 0; i < digits; ++i) scale *= 10;
    std::string fraction = std::to_string(a % scale);
    fraction.insert(0, static_cast<std::size_t>(digits) - fraction.size(), '0');
    return (negative ? "-" : "") + std::to_string(a / scale) + "." + fraction;
}

// ---- The shape of each suite's files (what the official loaders read) ----

inline int functions(int year) {
    return year == 2017 ? 30 : 12;
}

/// Stacked matrices in M_k_Dd.txt: the official loaders read 10 (2017, k >= 20) or 12 (2022,
/// k >= 9) for the compositions, 1 otherwise.
inline int matrices(int year, int f) {
    if (year == 2017) return f >= 20 ? 10 : 1;
    return f >= 9 ? 12 : 1;
}

/// Rows of 100 values in shift_data_k.txt. The loaders read as many shift rows as matrices, but
/// the official files have 10 rows for 2017 F21-F30 and 2022 F8-F12 and one row otherwise, so
/// this writes 10 for the compositions and 1 otherwise (only the first rows matter: the
/// compositions use at most 6).
inline int shift_rows(int year, int f) {
    if (year == 2017) return f >= 20 ? 10 : 1;
    return f >= 9 ? 10 : 1;
}

/// Permutations of 1..D in shuffle_data_k_Dd.txt (0: no file read): 2017 F11-F20 one, F29-F30
/// ten (one per component); 2022 F6-F8 one.
inline int permutations(int year, int f) {
    if (year == 2017) return (f >= 11 && f <= 20) ? 1 : (f >= 29 ? 10 : 0);
    return (f >= 6 && f <= 8) ? 1 : 0;
}

/// The dimensions in which the official code defines function f and ships its data. 2017: no
/// data at D = 2 for the hybrids (F11-F20) nor at D = 20 for F11-F19, F29, F30; at D = 2 the code
/// also declares F21, F22, F29, F30 undefined (data or not). 2022: F6-F8 not at D = 2.
inline std::vector<int> official_dimensions(int year, int f) {
    std::vector<int> dims;
    if (year == 2017) {
        const bool hybrid = (f >= 11 && f <= 19) || f >= 29;
        if (f <= 10 || (f >= 23 && f <= 28)) dims.push_back(2);
        dims.push_back(10);
        if (!hybrid) dims.push_back(20);
        for (const int d : {30, 50, 100}) dims.push_back(d);
    } else {
        if (f <= 5 || f >= 9) dims.push_back(2);
        dims.push_back(10);
        dims.push_back(20);
    }
    return dims;
}

/// The dimensions of the synthetic layer: 10 and 20 where the official data has them, and 30
/// for the 2017 functions the official data lacks at 20 (F11-F19, F29, F30).
inline std::vector<int> synthetic_dimensions(int year, int f) {
    std::vector<int> dims;
    for (const int d : official_dimensions(year, f))
        if (d == 10 || d == 20) dims.push_back(d);
    if (year == 2017 && dims.size() == 1) dims.push_back(30);
    return dims;
}

// ---- The synthetic data ----

/// Entry i of shift row r of function f: an integer k in [-80e6, 80e6], the shift k / 10^6.
inline std::int64_t shift_integer(std::uint64_t seed, int year, int f, int row, int i) {
    auto g = stream(seed, {1, static_cast<std::uint64_t>(year), static_cast<std::uint64_t>(f),
                           static_cast<std::uint64_t>(row), static_cast<std::uint64_t>(i)});
    return g.uniform(-80'000'000, 80'000'000);
}
inline double shift_value(std::uint64_t seed, int year, int f, int row, int i) {
    return decimal_value(shift_integer(seed, year, f, row, i), 6);
}

/// The entries of M_f_Dd.txt, row-major, matrices() of them stacked: k / 10^8 with |k| <=
/// sqrt(3/D) 10^8, so that a row's norm is about 1 (the code needs no orthogonality).
inline std::vector<std::int64_t> matrix_integers(std::uint64_t seed, int year, int f, int dim) {
    const auto bound = static_cast<std::int64_t>(std::sqrt(3.0 / dim) * 1e8);
    auto g = stream(
        seed, {2, static_cast<std::uint64_t>(year), static_cast<std::uint64_t>(f), static_cast<std::uint64_t>(dim)});
    std::vector<std::int64_t> out(static_cast<std::size_t>(matrices(year, f)) * dim * dim);
    for (auto& k : out) k = g.uniform(-bound, bound);
    return out;
}

/// permutations() permutations of 1..dim, concatenated (1-based, as the official files).
inline std::vector<int> shuffle(std::uint64_t seed, int year, int f, int dim) {
    auto g = stream(
        seed, {3, static_cast<std::uint64_t>(year), static_cast<std::uint64_t>(f), static_cast<std::uint64_t>(dim)});
    std::vector<int> out;
    for (int p = 0; p < permutations(year, f); ++p) {
        std::vector<int> perm(static_cast<std::size_t>(dim));
        for (int i = 0; i < dim; ++i) perm[static_cast<std::size_t>(i)] = i + 1;
        for (int i = dim - 1; i > 0; --i) std::swap(perm[static_cast<std::size_t>(i)], perm[g.next() % (i + 1)]);
        out.insert(out.end(), perm.begin(), perm.end());
    }
    return out;
}

inline std::string shift_file(std::uint64_t seed, int year, int f) {
    std::string text;
    for (int r = 0; r < shift_rows(year, f); ++r) {
        for (int i = 0; i < 100; ++i) {
            text += i ? " " : "";
            text += decimal_text(shift_integer(seed, year, f, r, i), 6);
        }
        text += '\n';
    }
    return text;
}

inline std::string matrix_file(std::uint64_t seed, int year, int f, int dim) {
    const auto entries = matrix_integers(seed, year, f, dim);
    std::string text;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        text += decimal_text(entries[i], 8);
        text += (i + 1) % static_cast<std::size_t>(dim) == 0 ? "\n" : " ";
    }
    return text;
}

inline std::string shuffle_file(std::uint64_t seed, int year, int f, int dim) {
    std::string text;
    const auto perm = shuffle(seed, year, f, dim);
    for (std::size_t i = 0; i < perm.size(); ++i) text += (i ? "\t" : "") + std::to_string(perm[i]);
    return text + "\n";
}

/// Writes into `dir` (created if need be) every file the official loader of `year` reads for
/// the functions and dimensions of synthetic_dimensions().
inline void write_input_data(const std::filesystem::path& dir, int year, std::uint64_t seed = kSeed) {
    std::filesystem::create_directories(dir);
    const auto put = [&](const std::string& name, const std::string& text) {
        std::ofstream out(dir / name, std::ios::binary);
        out << text;
        if (!out) throw std::runtime_error("cannot write " + (dir / name).string());
    };
    for (int f = 1; f <= functions(year); ++f) {
        put("shift_data_" + std::to_string(f) + ".txt", shift_file(seed, year, f));
        for (const int d : synthetic_dimensions(year, f)) {
            const std::string suffix = std::to_string(f) + "_D" + std::to_string(d) + ".txt";
            put("M_" + suffix, matrix_file(seed, year, f, d));
            if (permutations(year, f) > 0) put("shuffle_data_" + suffix, shuffle_file(seed, year, f, d));
        }
    }
}

/// The optimum of the synthetic function: the first dim entries of its first shift row.
inline std::vector<double> synthetic_optimum(std::uint64_t seed, int year, int f, int dim) {
    std::vector<double> o(static_cast<std::size_t>(dim));
    for (int i = 0; i < dim; ++i) o[static_cast<std::size_t>(i)] = shift_value(seed, year, f, 0, i);
    return o;
}

// ---- The points (the same for both layers; those near o take o as given) ----

/// Point p (0 <= p < kPoints) of function f of `year` in dimension o.size(), o its optimum (the
/// first shift row, as the data gives it). Independent of the data's seed.
inline std::vector<double> point(int year, int f, std::span<const double> o, int p) {
    const int dim = static_cast<int>(o.size());
    std::vector<double> x(o.size());
    if (p == 0) {
        x.assign(o.begin(), o.end());
    } else if (p >= kNearFirst && p <= kNearLast) {
        // One direction for all six radii: m_i in [-10^6, 10^6], o_i + m_i / 10^(6+p).
        auto g = stream(0x0c0ffee, {4, static_cast<std::uint64_t>(year), static_cast<std::uint64_t>(f),
                                    static_cast<std::uint64_t>(dim)});
        for (std::size_t i = 0; i < x.size(); ++i) x[i] = o[i] + decimal_value(g.uniform(-1'000'000, 1'000'000), 6 + p);
    } else {
        auto g = stream(0x0c0ffee, {5, static_cast<std::uint64_t>(year), static_cast<std::uint64_t>(f),
                                    static_cast<std::uint64_t>(dim), static_cast<std::uint64_t>(p)});
        const std::int64_t bound = p <= 12 ? 100'000'000 : 1'000'000'000;  // 100 or 1000, in 10^-6
        for (auto& xi : x) {
            if (p == 15)
                xi = (g.next() >> 63) ? 100.0 : -100.0;
            else
                xi = decimal_value(g.uniform(-bound, bound), 6);
        }
    }
    return x;
}

}  // namespace pride::test::cec_synthetic

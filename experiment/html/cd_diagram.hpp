#pragma once
// Demsar's critical-difference diagram (J. Demsar, "Statistical comparisons of classifiers over
// multiple data sets", JMLR 7:1-30, 2006, figure 1): an axis of average ranks, 1 at the left;
// each algorithm's name joined by a line to its rank on the axis, the better half of the names at
// the left, the worse half at the right, so that no two lines cross; below the axis a thick bar
// joining each group of algorithms not significantly different (critical_difference.hpp's
// cliques); above it the critical difference drawn to the axis' scale. The layout is computed in
// ranks and rows (cd_layout, what tests check), then drawn with cairo as SVG.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "experiment/report/critical_difference.hpp"
#include "framework/output_files.hpp"

namespace pride::html {

struct CdLayout {
    // The axis, in average ranks: from 1 (left) to the number of algorithms, or further when the
    // critical difference is longer than the axis, to a whole rank.
    double low = 1, high = 2;
    struct Name {
        std::size_t algorithm = 0;  // index into the average ranks
        double rank = 0;
        bool left = true;     // its name at the left end of its line, else at the right
        std::size_t row = 0;  // 0: the row nearest the axis
    };
    std::vector<Name> names;  // in order of average rank, best first (ties: in index order)
    struct Bar {
        double from = 0, to = 0;  // ranks of its best and worst algorithm
        std::size_t level = 0;    // 0: nearest the axis; bars that would touch get other levels
    };
    std::vector<Bar> bars;  // one per clique, in the cliques' order
    std::size_t levels = 0;
    double cd_from = 1, cd_to = 1;  // the critical difference as a segment of the axis' scale, from rank 1
};

/// The layout of the diagram: the first ceil(k/2) algorithms by rank at the left, in rows 0, 1,
/// ... (the best nearest the axis), the others at the right, the worst nearest the axis; each
/// clique a bar from its best to its worst rank, on the lowest level where it does not meet a bar
/// already placed (bars sharing an algorithm meet).
CdLayout cd_layout(std::span<const double> average_ranks, const stats::CriticalDifference& cd);

/// Draws the diagram of `layout` as SVG into `file` (and closes it), `names` the algorithms (in
/// the average ranks' order), under `title` and `subtitle`. InputError naming the file when it
/// cannot be written.
void write_cd_diagram(const CdLayout& layout, const std::vector<std::string>& names, const std::string& title,
                      const std::string& subtitle, OutputFiles::File& file);

}  // namespace pride::html

#pragma once
// Inside the CEC 2020 real-world suite: the tables restated from the organisers' data files and the
// problems written in the other source files. Each problem function returns f(x) and writes the
// inequality values, then the equality values, into c.
#include <cstddef>

namespace pride::continuous::cec2020rw::detail {

struct AdmittanceEntry {
    int row, column;
    double g, b;  // Y = G + jB
};

extern const double kFeed[7][59];      // RC51-RC54: FunctionRM_feed.txt
extern const double kDairy[14][64];    // RC55-RC57: FunctionRM_dairy.txt
extern const AdmittanceEntry kPs1Y[];  // RC34: FunctionPS1_G.txt, FunctionPS1_B.txt
extern const std::size_t kPs1YCount;
extern const AdmittanceEntry kPs2Y[];  // RC35, RC36, RC41: FunctionPS2_G.txt, FunctionPS2_B.txt
extern const std::size_t kPs2YCount;
extern const AdmittanceEntry kPs11Y[];  // RC37-RC39: FunctionPS11_G.txt, FunctionPS11_B.txt
extern const std::size_t kPs11YCount;
extern const double kPs1P[30], kPs1Q[30], kPs11P[30], kPs11Q[30];
extern const double kPs2P[38][6], kPs2Q[38][6];  // RC35, RC36, RC40-RC43: loads and their exponents
extern const double kPs14Lines[37][6];           // RC40, RC42, RC43: from, to, R, X, B/2, tap

}  // namespace pride::continuous::cec2020rw::detail

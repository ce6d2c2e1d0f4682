// bench/mo_bench's pride runs on DTLZ1 and DTLZ2 at M = 3 (mo_bench_pride.hpp).
#include "bench/mo_bench_pride.hpp"
#include "problems/multiobjective/dtlz.hpp"

namespace pride::mo_bench {

void bench_pride_dtlz(const Settings& s, const References& r) {
    using namespace pride::multiobjective;
    bench_pride_all(s, "dtlz1", Dtlz1(3), r.dtlz1);
    bench_pride_all(s, "dtlz2", Dtlz2(3), r.dtlz2);
}

}  // namespace pride::mo_bench

// bench/mo_bench's pride runs on ZDT1-4, 6 (mo_bench_pride.hpp).
#include "bench/mo_bench_pride.hpp"
#include "problems/multiobjective/zdt.hpp"

namespace pride::mo_bench {

void bench_pride_zdt(const Settings& s, const References& r) {
    using namespace pride::multiobjective;
    bench_pride_all(s, "zdt1", Zdt1(30), r.zdt1);
    bench_pride_all(s, "zdt2", Zdt2(30), r.zdt2);
    bench_pride_all(s, "zdt3", Zdt3(30), r.zdt3);
    bench_pride_all(s, "zdt4", Zdt4(10), r.zdt4);
    bench_pride_all(s, "zdt6", Zdt6(10), r.zdt6);
}

}  // namespace pride::mo_bench

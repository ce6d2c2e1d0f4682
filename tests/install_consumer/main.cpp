// Uses an installed pride as a library: lists the registry, runs pso on sphere and checks that a
// bad parameter is reported as pride::InputError. Exit status 0 only when every check holds.
#include <cmath>
#include <cstdio>
#include <exception>

#include "engine/registry.hpp"
#include "engine/run.hpp"
#include "experiment/campaign/identity.hpp"
#include "framework/error.hpp"

namespace {

int failures = 0;

void expect(bool ok, const char* what) {
    if (!ok) {
        std::fprintf(stderr, "FAILED: %s\n", what);
        ++failures;
    }
}

}  // namespace

int main() {
    try {
        const auto& entries = pride::engine::algorithms().entries();
        std::printf("%zu algorithms:", entries.size());
        for (const auto& e : entries) std::printf(" %s", e.name.c_str());
        std::printf("\n");
        expect(!entries.empty(), "the registry lists algorithms");
        expect(pride::engine::algorithms().find("pso") != nullptr, "pso is registered");

        const pride::engine::Problem sphere{pride::engine::ContinuousSpec{"sphere", 5}};
        pride::engine::Budget budget;
        budget.evaluations = 2000;
        const pride::engine::AlgorithmSpec pso{"pso", {}};
        const auto result = pride::engine::run(pso, sphere, budget, 1);
        std::printf("pso on sphere, dim 5: best %.17g after %lld evaluations\n", result.best_f,
                    static_cast<long long>(result.evaluations));
        expect(result.evaluations == 2000, "exactly 2000 evaluations");
        expect(std::isfinite(result.best_f) && result.best_f < 1.0, "a finite best value below 1");

        // The experiment layer (pride::experiment): a campaign's budget as the store identifies it.
        pride::campaign::Campaign campaign;
        campaign.budget.evaluations = 2000;
        const std::string budget_text = pride::campaign::budget_definition(campaign);
        std::printf("campaign budget: %s\n", budget_text.c_str());
        expect(budget_text.find("2000") != std::string::npos, "the campaign's budget names its 2000 evaluations");

        pride::engine::AlgorithmSpec bad = pso;
        bad.params.set("no_such_parameter", 1.0);
        try {
            pride::engine::run(bad, sphere, budget, 1);
            expect(false, "an unknown parameter throws pride::InputError");
        } catch (const pride::InputError& e) {
            std::printf("unknown parameter: %s\n", e.what());
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "FAILED: unexpected exception: %s\n", e.what());
        return 1;
    }
    return failures == 0 ? 0 : 1;
}

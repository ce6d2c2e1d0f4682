#pragma once
// The concrete multi-objective problem types the engine runs, as one variant (as targets.hpp is
// for single-objective ones): a registration file visits it once per run, and the run is typed.
// Four types: the catalog (one type for ZDT and DTLZ), a grid through each of the two box
// encodings, and a user's function; and beside them a grid on cell chains (MoChainTarget).
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "framework/error.hpp"
#include "framework/problem.hpp"
#include "problems/grid/connectors.hpp"
#include "problems/grid/encodings.hpp"
#include "problems/grid/multiobjective.hpp"
#include "problems/multiobjective/catalog.hpp"

namespace pride::engine {

/// A user's function of M objectives: the edge where a call goes through std::function. With a
/// batch function, a population is one call.
class MoCallbackProblem {
  public:
    using Scalar = std::function<void(std::span<const double>, std::span<double>)>;
    using Batch = std::function<void(MatrixView, Matrix&)>;

    MoCallbackProblem(std::string name, std::vector<double> lower, std::vector<double> upper, std::size_t objectives,
                      Scalar scalar, Batch batch)
        : shared_(std::make_shared<const Shared>(Shared{std::move(name), std::move(lower), std::move(upper), objectives,
                                                        std::move(scalar), std::move(batch)})) {}

    std::size_t dimension() const noexcept { return shared_->lower.size(); }
    std::span<const double> lower() const noexcept { return shared_->lower; }
    std::span<const double> upper() const noexcept { return shared_->upper; }
    std::size_t objectives() const noexcept { return shared_->objectives; }
    const std::string& name() const noexcept { return shared_->name; }

    void evaluate(std::span<const double> x, std::span<double> f) {
        if (shared_->scalar) {
            shared_->scalar(x, f);
            return;
        }
        // Only a batch function: a one-column batch.
        const Eigen::Map<const Matrix> point(x.data(), static_cast<Eigen::Index>(x.size()), 1);
        one_.resize(static_cast<Eigen::Index>(f.size()), 1);
        shared_->batch(point, one_);
        std::copy(one_.data(), one_.data() + f.size(), f.begin());
    }
    void evaluate_batch(MatrixView points, Matrix& values) {
        if (shared_->batch) {
            shared_->batch(points, values);
            return;
        }
        const auto n = static_cast<std::size_t>(points.rows()), m = objectives();
        for (Eigen::Index j = 0; j < points.cols(); ++j)
            shared_->scalar(std::span<const double>(points.col(j).data(), n),
                            std::span<double>(values.col(j).data(), m));
    }

  private:
    struct Shared {
        std::string name;
        std::vector<double> lower, upper;
        std::size_t objectives;
        Scalar scalar;
        Batch batch;
    };
    std::shared_ptr<const Shared> shared_;
    Matrix one_;  // scratch of the batch-only route
};

using MoGridLine = grid::MultiObjectivePaths<grid::LineEncoding<grid::SelectableConnector>>;
using MoGridFree = grid::MultiObjectivePaths<grid::FreeEncoding<grid::SelectableConnector>>;
using MoVariant = std::variant<multiobjective::Benchmark, MoGridLine, MoGridFree, MoCallbackProblem>;

struct MoTarget {
    MoVariant problem;
};

/// A grid of several criteria on cell chains (the chain encoding), for the algorithms that have
/// chain operators (AlgorithmEntry::run_multiobjective_chain).
using MoGridChain = grid::MultiObjectiveChains;
struct MoChainTarget {
    MoGridChain problem;
};

}  // namespace pride::engine

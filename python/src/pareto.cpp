// pride.hypervolume, pride.igd, pride.igd_plus, pride.epsilon_additive, pride.nondominated_sort and
// pride.crowding_distance, pride.attainment_surface: framework/pareto/ on numpy arrays. A set is an (n, M) array, one
// row per point; read row-major it is the (M, n) matrix, one column per point, that framework/pareto takes, so no copy
// is made of a C-contiguous array of doubles.
#include <Eigen/Core>

#include <cstring>
#include <string>
#include <vector>

#include "common.hpp"
#include "framework/pareto/attainment.hpp"
#include "framework/pareto/hypervolume.hpp"
#include "framework/pareto/indicators.hpp"
#include "framework/pareto/sorting.hpp"

namespace pride::python {
namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// An (n, M) array of objective vectors, seen as the (M, n) matrix.
struct PointSet {
    Array array;
    Eigen::Map<const Matrix> f() const { return {array.data(), array.shape(1), array.shape(0)}; }
};

PointSet point_set(const py::object& o, const std::string& what) {
    PointSet s{real_array(o, what)};
    require(s.array.ndim() == 2, what,
            "must be an (n, M) array, one row per point, got " + std::to_string(s.array.ndim()) + " dimensions");
    require(s.array.shape(1) >= 1, what, "has no objectives (0 columns)");
    return s;
}

/// Both arguments name the mismatch: either may be the wrong one.
void same_objectives(py::ssize_t a, const char* a_name, py::ssize_t b, const char* b_name) {
    require(a == b, a_name,
            std::to_string(a) + " objectives, " + b_name + ": " + std::to_string(b) + " (they must be equal)");
}

Array reference_point(const py::object& ref, const PointSet& s) {
    Array r = real_array(ref, "ref");
    require(r.ndim() == 1, "ref", "must be one point (M,), got " + std::to_string(r.ndim()) + " dimensions");
    same_objectives(s.array.shape(1), "points", r.shape(0), "ref");
    return r;
}

double hypervolume(const py::object& points, const py::object& ref) {
    const PointSet s = point_set(points, "points");
    const Array r = reference_point(ref, s);
    return pareto::hypervolume(s.f(), std::span<const double>(r.data(), static_cast<std::size_t>(r.shape(0))));
}

py::array_t<double> contributions(const py::object& points, const py::object& ref) {
    const PointSet s = point_set(points, "points");
    const Array r = reference_point(ref, s);
    const std::vector<double> c =
        pareto::contributions(s.f(), std::span<const double>(r.data(), static_cast<std::size_t>(r.shape(0))));
    py::array_t<double> out(static_cast<py::ssize_t>(c.size()));
    std::copy(c.begin(), c.end(), out.mutable_data());
    return out;
}

template <double (*Indicator)(const MatrixView&, const MatrixView&)>
double against_front(const py::object& points, const py::object& front) {
    const PointSet a = point_set(points, "points");
    const PointSet z = point_set(front, "front");
    same_objectives(a.array.shape(1), "points", z.array.shape(1), "front");
    return Indicator(a.f(), z.f());
}

py::array_t<std::int64_t> nondominated_sort(const py::object& points) {
    const PointSet s = point_set(points, "points");
    std::vector<std::size_t> rank(static_cast<std::size_t>(s.array.shape(0)));
    pareto::SortScratch scratch;
    pareto::nondominated_sort(s.f(), rank, scratch);
    py::array_t<std::int64_t> out(static_cast<py::ssize_t>(rank.size()));
    std::copy(rank.begin(), rank.end(), out.mutable_data());
    return out;
}

py::array_t<double> crowding_distance(const py::object& points) {
    const PointSet s = point_set(points, "points");
    std::vector<std::size_t> members(static_cast<std::size_t>(s.array.shape(0)));
    for (std::size_t k = 0; k < members.size(); ++k) members[k] = k;
    py::array_t<double> out(static_cast<py::ssize_t>(members.size()));
    pareto::SortScratch scratch;
    pareto::crowding_distance(s.f(), members, std::span<double>(out.mutable_data(), members.size()), scratch);
    return out;
}

py::array_t<double> attainment_surface(const py::object& runs, const py::object& k) {
    if (!py::isinstance<py::list>(runs) && !py::isinstance<py::tuple>(runs))
        throw py::type_error("runs: expected a list of (n, 2) arrays, one per run, got " + type_name(runs));
    std::vector<Matrix> sets;
    const auto seq = py::reinterpret_borrow<py::sequence>(runs);
    for (std::size_t i = 0; i < seq.size(); ++i) {
        const std::string what = "runs[" + std::to_string(i) + "]";
        const Array a = real_array(seq[i], what);
        require(a.ndim() == 2 && (a.shape(1) == 2 || a.shape(0) == 0), what,
                "must be an (n, 2) array, one row per point of two objectives");
        sets.emplace_back(Eigen::Map<const Matrix>(a.data(), 2, a.shape(0)));
    }
    const std::int64_t level = integer_arg(k, "k");
    require(level >= 1 && static_cast<std::size_t>(level) <= std::max<std::size_t>(sets.size(), 1), "k",
            "must be in [1, " + std::to_string(sets.size()) + "] (the number of runs), got " + std::to_string(level));
    const Matrix s = pareto::attainment_surface(sets, static_cast<std::size_t>(level));
    py::array_t<double> out({static_cast<py::ssize_t>(s.cols()), py::ssize_t{2}});
    if (s.size() > 0) std::memcpy(out.mutable_data(), s.data(), sizeof(double) * static_cast<std::size_t>(s.size()));
    return out;
}

}  // namespace

void bind_pareto(py::module_& m) {
    m.def("hypervolume", &hypervolume, py::arg("points"), py::arg("ref"));
    m.def("hypervolume_contributions", &contributions, py::arg("points"), py::arg("ref"));
    m.def("igd", &against_front<&pareto::igd>, py::arg("points"), py::arg("front"));
    m.def("igd_plus", &against_front<&pareto::igd_plus>, py::arg("points"), py::arg("front"));
    m.def("epsilon_additive", &against_front<&pareto::epsilon_additive>, py::arg("points"), py::arg("front"));
    m.def("nondominated_sort", &nondominated_sort, py::arg("points"));
    m.def("crowding_distance", &crowding_distance, py::arg("points"));
    m.def("attainment_surface", &attainment_surface, py::arg("runs"), py::arg("k"));
}

}  // namespace pride::python

#pragma once
// The continuous problems by name, for the command line, campaigns, Python and the benchmarks: each
// name makes a Function (function.hpp) in a dimension and an instance. The concrete classes are
// compiled in catalog.cpp only, so code that runs problems by name never includes them.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "framework/registry.hpp"
#include "problems/continuous/function.hpp"

namespace pride::continuous {

/// What an instance number means for a function.
enum class Instances {
    transform,  // scalable: 0 as defined, k >= 1 shifted and rotated (instance.hpp)
    none,       // a fixed instance (fixed dimension, or a shifted-* alias): 0 only
    coco,       // BBOB: COCO's instances, k >= 1 (default 1)
};

struct CatalogEntry {
    std::size_t min_dim = 1;
    std::size_t fixed_dim = 0;      // 0: any dimension >= min_dim
    std::vector<std::size_t> dims;  // not empty: the only dimensions (CEC: where the official data is)
    Instances instances = Instances::transform;
    std::string suite;  // "bbob", "classic" (Yao et al. 1999's F1-F23), "cec2017", "cec2022", or empty
    int number = 0;     // its number in the suite (bbob-f3: 3, yao-f9: 9)
    std::function<Function(std::size_t dim, std::int64_t instance)> make;
};

const Registry<CatalogEntry>& catalog();

/// The instance a problem gets when none is given: 0, or 1 for BBOB (COCO counts from 1).
std::int64_t default_instance(const CatalogEntry& entry);

/// The problem `name` in dimension `dim`, instance `instance` (empty: the default). InputError
/// for an unknown name, a bad dimension (blamed on `dim_source`, the option or input it came
/// from) or an instance the function does not have (blamed on "instance").
Function make_function(std::string_view name, std::int64_t dim, std::optional<std::int64_t> instance = {},
                       const std::string& dim_source = "dim");

}  // namespace pride::continuous

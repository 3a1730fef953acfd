/// @file errors.cpp
#include "core/errors.hpp"

#include <cstdio>

namespace stepwise {

namespace {
std::string describe(const std::string& object, const std::string& stage, std::uint64_t step,
                     double time, const std::string& what) {
    char when[96];
    std::snprintf(when, sizeof when, "step %llu (t = %.6g s)", static_cast<unsigned long long>(step), time);
    return std::string(when) + ", stage '" + stage + "': object '" + object + "': " + what;
}
}  // namespace

SimulationError::SimulationError(std::string objectName, std::string stageName, std::uint64_t step,
                                 double time, const std::string& what)
    : std::runtime_error(describe(objectName, stageName, step, time, what)),
      object_(std::move(objectName)),
      stage_(std::move(stageName)),
      step_(step) {}

}  // namespace stepwise

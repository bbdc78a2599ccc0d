#pragma once
// Theory predictions as JSON: `granmc theory SCENE` and the "theory" entry of the run summary.
#include <nlohmann/json.hpp>

#include "kernel/core/scene.hpp"
#include "kernel/theory/scene_theory.hpp"

namespace granmc {

/// The cooling-state prediction's scalars and Haff's law at the sample times.
nlohmann::json cooling_state_json(const theory::CoolingStatePrediction& p);

/// Everything the theory says about a scene (what applies is listed under "applies").
nlohmann::json scene_theory_json(const Scene& scene);

}  // namespace granmc

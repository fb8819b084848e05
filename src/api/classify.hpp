#pragma once
/// classify: the initiating mode (rest, slide, rock, slide-rock) of a block at rest under peak
/// accelerations (docs/methods.md s.2).
#include "api/json.hpp"
#include "sliding/block_spec.hpp"
#include "sliding/initiation.hpp"

namespace freestand::api {

/// An InputError about a request names the request's field (`mu_s`, `box.half_width_m`), never a
/// command-line option: the command line and the Python module each rename it to what their
/// user typed (cli/flag_names.hpp, python/src/parameter_names.cpp).
struct ClassifyRequest {
    sliding::BoxSpec box;
    double mu_s = 0.0;   ///< static friction coefficient, in [0, 2]
    double a_h_g = 0.0;  ///< peak horizontal acceleration, g, >= 0
    double av_g = 0.0;   ///< peak vertical acceleration, g, in [0, 1), taken downward
};

struct ClassifyResult {
    ClassifyRequest request;
    sliding::PeakInitiation initiation;
};

/// The checked request's initiating mode per edge; InputError naming the field otherwise.
ClassifyResult classify(const ClassifyRequest& request);

/// `classify --json`.
json to_json(const ClassifyResult& result);

/// One edge's initiation: mode, edge, tan(alpha), A, mu_crit (or its reason), the deciding rule.
json to_json(const sliding::Initiation& initiation);

/// "left" or "right".
const char* edge_name(block::Edge e);

}  // namespace freestand::api

#pragma once
/// simulate: the time history of a free-standing block under a record or a sine
/// (docs/methods.md s.6-s.11). One request runs one of five models: the planar rigid block;
/// biaxial sliding when a second horizontal component is given (s.10); the reduced-order
/// flexible body (s.10); two rigid units joined by a tunnel (s.10); or the rigid body in three
/// dimensions under all components at once (s.11).
#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "api/json.hpp"
#include "core/record.hpp"
#include "dynamics/biaxial.hpp"
#include "dynamics/body3d.hpp"
#include "dynamics/flexible.hpp"
#include "dynamics/pair.hpp"
#include "dynamics/simulate.hpp"
#include "sliding/block_spec.hpp"

namespace freestand::api {

/// The base motion: records (each sample times scale) or a sine, never both.
struct SimulateExcitation {
    std::optional<core::Record> horizontal;    ///< x component, m/s^2
    std::optional<core::Record> vertical;      ///< up, m/s^2; only with horizontal
    std::optional<core::Record> horizontal_y;  ///< y component with horizontal: biaxial sliding
    double scale = 1.0;                        ///< factor on every record's samples
    std::optional<dynamics::SineSpec> sine;    ///< planar sine (its phase_deg is not used)
    /// Biaxial sine: x = A sin(2 pi f t), y the same led by phase_deg (biaxial sliding).
    std::optional<dynamics::SineSpec> sine_y;
};

/// The second of two units joined by a tunnel (planar, the same base motion).
struct JoinedUnit {
    sliding::BoxSpec box;           ///< errors name unit2.box.*
    double mu_s = 0.0;              ///< unit2.mu_s, in [0, 2]
    std::optional<double> mu_k;     ///< unit2.mu_k, in [0, mu_s]; default mu_s
    std::optional<double> restitution;  ///< unit2.restitution, in [0, 1]; default Housner's
    double tunnel_height_m = 0.0;   ///< tunnel_height_m above the base, in [0, 1000]
};

/// The 3D body (docs/methods.md s.11): a box footprint 2 half_x x 2 half_y centred under the
/// CG, uniform inertia of a box of height total_height_m. Errors name body3d.*.
struct Body3dSpec {
    double half_x_m = 0.0;
    double half_y_m = 0.0;
    double cg_height_m = 0.0;
    double mass_kg = 1.0;
    std::optional<double> total_height_m;  ///< default 2 cg_height_m
    /// The CG's plan offset from the footprint's centre, m: the body then stands on the same
    /// 2 half_x_m x 2 half_y_m rectangle with the CG off its middle (|offset| < half-width).
    double cg_x_m = 0.0, cg_y_m = 0.0;
    /// Principal moments of inertia about the CG along x, y and the vertical, kg m^2 (each > 0);
    /// default: the uniform box of the footprint and the total height.
    std::optional<std::array<double, 3>> inertia_cg_kgm2;
    double dt_s = 1e-4;                    ///< time step, s
    /// A rigid body's smooth phases taken whole between the steps (Body3dOptions::phases);
    /// false: every phase by steps, the scheme alone, to check it.
    bool phases = true;
};

/// An InputError about a request names its field (`mu_s`, `box.half_width_m`, `flexible.f`,
/// `unit2.mu_s`, `sine_y.amplitude_g`), never a command-line option.
struct SimulateRequest {
    sliding::BoxSpec box;
    double mu_s = 0.0;                    ///< static friction, in [0, 2]
    std::optional<double> mu_k;           ///< kinetic friction, in [0, mu_s]; default mu_s
    std::optional<double> restitution;    ///< on angular velocity, in [0, 1]; default Housner's
    std::optional<double> top_height_m;   ///< top corners for top_accel; default 2 x CG height
    dynamics::Integrator integrator = dynamics::Integrator::event;
    double cd_dt_s = 1e-4;                ///< central-difference step, s, > 0
    SimulateExcitation excitation;
    /// The flexible body (planar, alone), or with body3d the mode the 3D body carries along
    /// x and y at the one frequency.
    std::optional<dynamics::FlexibleMode> flexible;
    std::optional<JoinedUnit> unit2;                 ///< a second unit (planar, no series)
    /// The 3D body instead of `box`'s planar block: every component (x, y when given, vertical)
    /// at once. Takes mu_s, mu_k, restitution and flexible; top_height_m, integrator and unit2
    /// do not apply to it.
    std::optional<Body3dSpec> body3d;
    bool record_series = false;                      ///< fill the run's series
};

struct PlanarRun {
    dynamics::BlockModel model;
    dynamics::SimulationResult result;
};

struct BiaxialRun {
    dynamics::BiaxialModel model;
    dynamics::BiaxialResult result;
};

struct FlexibleRun {
    dynamics::FlexibleModel model;
    dynamics::FlexibleResult result;
    double rigid_above_hz = 0.0;  ///< where the mode moves with the base (rigid_limit_hz)
};

struct PairRun {
    std::array<dynamics::BlockModel, 2> units;
    double tunnel_height_m = 0.0;
    dynamics::PairResult result;
};

struct Body3dRun {
    dynamics::Body3dModel model;
    dynamics::Body3dOptions options;
    dynamics::Body3dResult result;
};

struct SimulateResult {
    std::string excitation_label;  ///< the record's name or the sine's description
    std::variant<PlanarRun, BiaxialRun, FlexibleRun, PairRun, Body3dRun> run;
};

/// Checks the request (InputError naming the field), builds the model and the excitation and
/// runs it. NumericalError where an integrator cannot (e.g. a central-difference step above the
/// flexible mode's stability limit).
SimulateResult simulate(const SimulateRequest& request);

/// "event" or "cd" as the integrator, nullopt for anything else.
std::optional<dynamics::Integrator> integrator_named(const std::string& name);

/// `simulate --json`: the summary of the model that ran. top_height_name is what the caller
/// calls SimulateRequest::top_height_m, quoted where a default modal height is stated.
json to_json(const SimulateResult& result, const std::string& top_height_name = "top_height_m");

/// One planar block's summary, as `simulate --json` prints it.
json to_json(const dynamics::Summary& summary);

/// Why the flexible run's model is the one that ran (docs/methods.md s.10).
std::string model_reason(const FlexibleRun& run);

/// The defaults the flexible run took (cantilever modal mass and height), as sentences.
std::vector<std::string> assumptions(const FlexibleRun& run, const std::string& top_height_name);

}  // namespace freestand::api

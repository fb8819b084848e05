#pragma once
/// One rigid body in three dimensions on a moving base (docs/methods.md s.11): a convex
/// polygonal footprint that rests, slides and twists, rocks about an edge or a vertex, flies and
/// strikes the floor, under the three base components at once.
///
/// Nonsmooth time stepping (Moreau-Jean, as in Siconos): each step takes the positions at its
/// midpoint, finds the footprint's vertices on or below the floor there, and solves one
/// impulse problem for them at the velocity level (Newton's impact law on the normal relative
/// velocity, Coulomb's cone on the tangential one). Rest, sliding with twist, edge and vertex
/// rocking, flight and impacts are the same step with more or fewer vertices in contact; the
/// engine never has to enumerate transitions between them. docs/methods.md s.11 says why this
/// and not an event-driven engine, and how the indeterminate normal forces of four coplanar
/// contacts are made determinate.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/units.hpp"
#include "dynamics/biaxial.hpp"

namespace freestand::dynamics {

/// The body: mass, the footprint's vertices (plan coordinates relative to the CG, m, convex,
/// counter-clockwise), the CG's height above the footprint's plane, and the inertia tensor about
/// the CG in the body's axes (x, y along the plan, z up).
struct Body3d {
    double mass_kg = 1.0;
    std::vector<Eigen::Vector2d> footprint_m;
    double h_m = 0.0;
    Eigen::Matrix3d inertia_cg_kgm2 = Eigen::Matrix3d::Zero();

    /// Support function of the footprint: the farthest reach of a vertex from the CG's plan
    /// position along the plan direction (cos psi, sin psi), m.
    double reach_m(double psi_rad) const;
    /// Tilt at which the CG passes over the footprint's boundary when the body leans along the
    /// plan direction psi (docs/methods.md s.11): atan(reach_m(psi) / h), rad.
    double critical_tilt_rad(double psi_rad) const;
};

/// A box body: footprint the rectangle 2 half_x x 2 half_y centred under the CG, CG at
/// cg_height_m, uniform inertia of a box of that footprint and height total_height_m (default
/// 2 cg_height_m): I_x = M (4 half_y^2 + H^2) / 12, I_y = M (4 half_x^2 + H^2) / 12,
/// I_z = M (half_x^2 + half_y^2) / 3, where the CG is at mid-height. Throws InputError naming
/// half_x_m, half_y_m, h_m, mass_kg or total_height_m when one is not positive and finite, or
/// the body is taller than core::limits allows.
Body3d box_body(double half_x_m, double half_y_m, double cg_height_m, double mass_kg = 1.0,
                std::optional<double> total_height_m = std::nullopt);

/// One elastic mode per horizontal body axis, carried by the 3D body (docs/methods.md s.11,
/// the planar flexible body of s.10 in three dimensions): a modal mass m_s at height h_s above
/// the footprint's plane, on the body's vertical through the CG, that moves relative to the
/// body along its own x and y (modal coordinates q_x, q_y) with the fixed-base frequencies f_x,
/// f_y and the damping zeta. The rest of the body (mass M - m_s, with the first and second
/// moments that keep the whole body's CG and inertia at q = 0) is rigid and carries the
/// contacts. With the base held, q_x'' + 2 zeta omega_x q_x' + omega_x^2 q_x = -a_x (body
/// axes), and so for y.
struct Body3dMode {
    double frequency_x_hz = 0.0;
    double frequency_y_hz = 0.0;
    double damping = 0.02;        ///< zeta, [0, 1)
    double mass_fraction = 0.0;   ///< m_s / M, (0, 1)
    double height_m = 0.0;        ///< h_s above the footprint's plane, m
};

/// The body and its contact with the base.
struct Body3dModel {
    Body3d body;
    double mu_s = 0.0;  ///< static friction (a vertex that was not slipping)
    double mu_k = 0.0;  ///< kinetic friction (a vertex that was slipping), <= mu_s
    /// Newton's coefficient on a vertex's normal approach speed at an impact, in [0, 1]. 0: the
    /// vertex stays on the floor, so a body rocking about one edge and striking with the other
    /// keeps its angular momentum about the new edge (Housner's rule, generalised to 3D).
    double normal_restitution = 0.0;
    /// Restitution on angular velocity, the planar engine's r (docs/methods.md s.1, s.11): a
    /// step with an impact (a vertex arriving faster than gravity moves it in one step) is
    /// solved as a plastic impact (Housner's rule generalised), and then loses only the part
    /// (1 - r^2) / (1 - r_H^2) of the energy that impact took, r_H being Housner's value of
    /// the body's critical edge (housner_restitution). On that edge of a symmetric body this is
    /// the planar r: the angular speed leaves at r times. A glancing landing, which the plastic
    /// impact barely slows, stays barely slowed whatever r, so the result does not hang on how
    /// many landings the step resolves as impacts. Absent: the plastic impact's own. r = 1
    /// conserves the energy of free rocking; needs normal_restitution 0.
    std::optional<double> angular_restitution;
    /// The elastic modes (with_mode); absent: the rigid body.
    std::optional<Body3dMode> mode;
};
/// Housner's restitution for planar rocking about the footprint edge nearest the CG in plan
/// (the critical edge, the smallest critical tilt): 1 - 2 M d^2 / I_e, with d the CG's plan
/// distance from the edge and I_e the inertia about it (docs/methods.md s.1); at least 0.
double housner_restitution(const Body3d& body);

/// Validated model; mu_k defaults to mu_s. Throws InputError naming mu_s, mu_k,
/// normal_restitution or angular_restitution (ranges of core::limits; not both non-zero), or
/// the body's field that is not valid.
Body3dModel make_body3d_model(const Body3d& body, double mu_s,
                              std::optional<double> mu_k = std::nullopt,
                              double normal_restitution = 0.0,
                              std::optional<double> angular_restitution = std::nullopt);

/// The model carrying the mode. Throws InputError naming flexible.f_x, flexible.f_y,
/// flexible.zeta, flexible.mass or flexible.height when a frequency is not finite and > 0, zeta
/// is outside [0, 1), the fraction outside (0, 1), the height not > 0, or the modal mass takes
/// more of the body's second moment than it has (the rigid rest's inertia about its own CG
/// would not be positive definite).
Body3dModel with_mode(Body3dModel model, const Body3dMode& mode);

/// Longest step, s, with which simulate_body3d integrates the model's modes stably:
/// 2 (sqrt(1 + zeta_e^2) - zeta_e) / omega_e, the limit of its midpoint scheme on a damped
/// oscillator (docs/methods.md s.11), at the highest frequency omega_e of the modes against the
/// free rigid rest (the body in flight: contacts only lower it) and its damping zeta_e. Infinite
/// for the rigid body.
double body3d_modal_stable_step_s(const Body3dModel& model);

/// Contact state at a sample, by the vertices on the floor: rest and slide (three or more; slide
/// when any of them moves), edge (two), vertex (one), flight (none).
enum class ContactState { rest, slide, edge, vertex, flight };
inline constexpr std::size_t contact_state_count = 5;
/// "rest", "slide", "edge", "vertex", "flight".
const char* to_string(ContactState state);

/// The phases a rigid body may be taken through whole (docs/methods.md s.11): rocking on an
/// edge whose vertices stick, rocking on an edge whose vertices slip, sliding flat.
enum class Phase { edge_sticking, edge_slipping, flat_slide };
inline constexpr std::size_t phase_kind_count = 3;
/// "edge_sticking", "edge_slipping", "flat_slide".
const char* to_string(Phase phase);

struct Body3dOptions {
    /// Time step, s, rounded down to divide the excitation's sample step. First order: the
    /// error of the peaks falls in proportion to it (bench_dynamics, docs/methods.md s.11).
    double dt_s = 1e-4;
    /// The impulse problem of a step is solved by projected Gauss-Seidel sweeps over the
    /// contacts until a sweep changes no contact point's velocity by more than this fraction
    /// of g dt (the velocity gravity adds in one step).
    double solver_tol = 1e-12;
    std::size_t max_sweeps = 500;
    /// Relative Tikhonov weight on the impulses: the normal forces of more than three coplanar
    /// contacts are indeterminate, and the weight keeps the sweeps from drifting along them.
    /// The reported motion does not depend on it (docs/methods.md s.11).
    double regularization = 1e-8;
    double tail_s = 10.0;       ///< simulated time after the excitation ends
    /// Initial condition (the base at rest at t = 0): the body released at rest, leaning by
    /// initial_tilt_rad along the plan direction initial_lean_rad (from x towards y) on the
    /// footprint's support line in that direction (its edge, or its vertex on a diagonal).
    double initial_tilt_rad = 0.0;
    double initial_lean_rad = 0.0;
    /// Largest dt_s p accepted (see simulate_body3d): 0.02, fifty steps per radian of the
    /// free rocking motion's time scale.
    double max_step_p = 0.02;
    /// A step in which a vertex off the floor at the last step reaches it (an impact's arrival)
    /// is taken as this many steps of dt_s / arrival_substeps: the impact, the scheme's first-
    /// order error, falls within a sixteenth of the step (docs/methods.md s.11). 1: no split.
    std::size_t arrival_substeps = 16;
    /// A rigid body's smooth phases are taken as the few degrees of freedom they have
    /// (Dormand-Prince, their ends located), not by steps: rocking on a footprint edge whose
    /// two vertices stick or both slip, and sliding flat without turning (docs/methods.md
    /// s.11). false: every phase by steps (the scheme's own order).
    bool phases = true;
    bool record_series = true;
    double g_mps2 = units::g_mps2;
};

/// One output sample, at the excitation's sample times and through the tail.
struct Body3dSample {
    double time_s = 0.0;
    double slide_x_m = 0.0, slide_y_m = 0.0;  ///< footprint centre relative to the base
    double tilt_rad = 0.0;   ///< angle between the body's vertical axis and the vertical
    double tilt_over_critical = 0.0;  ///< tilt / critical tilt in the direction it leans
    double twist_rad = 0.0;  ///< rotation about the vertical
    double modal_x_m = 0.0, modal_y_m = 0.0;  ///< q_x, q_y of the mode (0 for the rigid body)
    ContactState state = ContactState::rest;
};

struct Body3dSummary {
    double tilt_max_rad = 0.0;
    double tilt_max_over_critical = 0.0;
    bool overturned = false;
    std::optional<double> overturn_time_s;
    double slide_max_m = 0.0;   ///< peak |u| of the footprint centre
    double twist_max_rad = 0.0; ///< peak |twist|
    double modal_max_m = 0.0;   ///< peak |q| of the mode, m (0 for the rigid body)
    std::array<double, contact_state_count> time_in_state_s{};
    std::size_t steps = 0;  ///< Moreau-Jean steps and the phases' Dormand-Prince steps
    std::size_t unconverged_steps = 0;  ///< steps whose impulses reached max_sweeps
    /// Time the rigid body spent in each kind of phase taken whole (Body3dOptions::phases), s,
    /// by Phase: the rest of its moving time went by steps.
    std::array<double, phase_kind_count> phase_time_s{};
    double end_time_s = 0.0;
    double pga_g = 0.0;  ///< peak |a_g| of the horizontal vector, g
    double wall_s = 0.0;
};

struct Body3dResult {
    Body3dSummary summary;
    std::vector<Body3dSample> series;
};

/// Simulates the body from rest, flat on the base, from t = 0 until the excitation's end plus
/// tail_s, or until it overturns (the tilt reaches pi/2). Throws InputError naming the option or
/// the excitation's field that is not valid, and when dt_s is past the step's accuracy limit:
/// dt_s p > max_step_p, with p = sqrt(M g R / I_O) the fastest rocking frequency parameter of
/// an edge or vertex (docs/methods.md s.1), as a step of that size misses the rocking motion,
/// or, with a mode, past body3d_modal_stable_step_s, where the step would amplify it.
Body3dResult simulate_body3d(const Body3dModel& model, const BiaxialExcitation& excitation,
                             const Body3dOptions& options = {});

}  // namespace freestand::dynamics

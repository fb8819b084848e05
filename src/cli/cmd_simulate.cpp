// `freestand simulate`: block time history under a record or a sine (api/simulate.hpp).
#include <fmt/format.h>
#include <iostream>

#include "api/simulate.hpp"
#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/simulate_biaxial.hpp"
#include "cli/simulate_body3d.hpp"
#include "cli/simulate_flexible.hpp"
#include "cli/simulate_pair.hpp"
#include "cli/series_label.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/readers.hpp"
#include "cli/usage_error.hpp"

// The command's own namespace: the command files share a unity build (src/cli/CMakeLists.txt).
namespace freestand::cli::simulate_command {

namespace {

const char* const usage =
    "[--model planar|3d] --block b=0.15,h=0.6,m=38 (3d: b=0.15,d=0.3,h=0.6,m=38[,height=H][,cgx=X,cgy=Y][,ixx=..,iyy=..,izz=..]) "
    "[--cg x,y] [--inertia I] [--top H] --mu 0.15 [--mu-k MU] "
    "[--restitution R] (--motion FILE[,VERTICAL_FILE] [--motion-y FILE] [--scale S] | "
    "--sine 0.8g,2Hz,5s[,ramp=1s] | --sine-y 0.8g,2Hz,5s[,ramp=1s][,phase=90]) "
    "[--flexible f=HZ[,zeta=Z][,mass=FRACTION][,height=M]] "
    "[--integrator event|cd] [--dt 1e-4] [--out series.csv] [--json] "
    "[--block2 ... [--cg2 ...] --mu2 MU [--mu-k2 MU] [--restitution2 R] --tunnel-height H]";

po::options_description simulate_options() {
    po::options_description desc("simulate options");
    desc.add_options()
        ("model", po::value<std::string>()->default_value("planar"),
         "planar | 3d: the rigid body in three dimensions under every component at once "
         "(docs/methods.md s.11)")
        ("block", po::value<std::string>()->required(),
         "b=half-width,h=CG height,m=mass (m, kg); with --model 3d b=half-width along x,"
         "d=half-width along y,h=CG height[,m=mass][,height=total height][,cgx=,cgy= CG offset "
         "from the footprint's centre][,ixx=,iyy=,izz= inertia about the CG, kg m^2]")
        ("cg", po::value<std::string>(),
         "x,y: CG x from the left edge and y above the base (m); or x=OFFSET,h=HEIGHT: x right "
         "of the base's centre, as classify and rock take it")
        ("inertia", po::value<double>(), "I_c about the CG (kg m^2)")
        ("top", po::value<double>(), "height of the top corners for top_accel (m; default 2 h)")
        ("mu", po::value<double>()->required(), "static friction coefficient, in [0, 2]")
        ("mu-k", po::value<double>(), "kinetic friction coefficient (default: --mu)")
        ("restitution", po::value<double>(),
         "restitution on angular velocity (default Housner; with --model 3d the generalised "
         "Housner impact's)")
        ("integrator", po::value<std::string>()->default_value("event"), "event | cd")
        ("dt", po::value<double>()->default_value(1e-4),
         "central-difference step, or the 3D body's step (s)")
        ("steps-only", "with --model 3d: every phase by steps (no phase taken whole), to check "
                       "the scheme alone")
        ("motion", po::value<std::string>(), "FILE[,VERTICAL_FILE] (.AT2, .V2, .csv)")
        ("scale", po::value<double>()->default_value(1.0), "factor on the --motion accelerations")
        ("sine", po::value<std::string>(), "A g,f Hz,T s[,ramp=t s]")
        ("motion-y", po::value<std::string>(),
         "FILE: second horizontal component with --motion; runs biaxial sliding")
        ("sine-y", po::value<std::string>(),
         "A g,f Hz,T s[,ramp=t s][,phase=DEG]: biaxial sliding under x = A sin(2 pi f t), "
         "y = A sin(2 pi f t + phase) (phase 0 by default)")
        ("flexible", po::value<std::string>(),
         "f=HZ[,zeta=RATIO][,mass=FRACTION][,height=M]: reduced-order flexible body (fixed-base "
         "frequency, modal damping, modal mass as a fraction of m, its height above the base; "
         "defaults zeta 0.02 and a uniform cantilever's 0.613 m at 0.726 x 2 h); with --model "
         "3d the mode along x and y at the one frequency, under every component")
        ("out", po::value<std::string>(), "write the time series CSV here")
        ("json", po::bool_switch(), "print the summary as JSON");
    add_pair_options(desc);
    return desc;
}

std::optional<double> opt_double(const po::variables_map& vm, const char* name) {
    if (!vm.count(name)) return std::nullopt;
    return vm[name].as<double>();
}

// Which options go together, as the command line spells them; the request's own consistency
// is api::simulate's to check.
bool three_d(const po::variables_map& vm) {
    const std::string model = vm["model"].as<std::string>();
    if (model != "planar" && model != "3d")
        throw UsageError(fmt::format("--model: expected planar or 3d; got \"{}\"", model));
    return model == "3d";
}

void require_option_set(const po::variables_map& vm) {
    if (vm.count("motion") + vm.count("sine") + vm.count("sine-y") != 1)
        throw UsageError("simulate: give exactly one of --motion, --sine and --sine-y");
    if (vm.count("motion-y") && !vm.count("motion"))
        throw UsageError("--motion-y: needs --motion (the x component)");
    const bool biaxial = vm.count("motion-y") || vm.count("sine-y");
    if (pair_requested(vm)) require_pair_options(vm);
    if (vm.count("flexible") && (pair_requested(vm) || (biaxial && !three_d(vm))))
        throw UsageError("--flexible: runs alone (no --motion-y, --sine-y or second unit; "
                         "--model 3d takes both components)");
    if (biaxial)
        for (const char* flag : {"restitution", "top"})
            if (vm.count(flag))
                throw UsageError(fmt::format("--{}: not used by the biaxial model (--motion-y, "
                                             "--sine-y), which has no rocking",
                                             flag));
}

// --motion FILE[,VERTICAL_FILE] [--motion-y FILE] as records.
void read_motion(const po::variables_map& vm, api::SimulateExcitation& e) {
    const std::string text = vm["motion"].as<std::string>();
    const std::vector<std::string> files = split_list(text);
    if (files.size() > 2 || files[0].empty() || (files.size() == 2 && files[1].empty()))
        throw UsageError(fmt::format("--motion: expected FILE[,VERTICAL_FILE]; got \"{}\"", text));
    std::string y_file;
    if (vm.count("motion-y")) {
        y_file = vm["motion-y"].as<std::string>();
        if (y_file.empty()) throw UsageError("--motion-y: expected a record FILE; got \"\"");
    }
    e.horizontal = core::read_record(files[0]);
    if (!y_file.empty()) e.horizontal_y = core::read_record(y_file);
    if (files.size() == 2) e.vertical = core::read_record(files[1]);
}

api::SimulateExcitation excitation_of(const po::variables_map& vm) {
    api::SimulateExcitation e;
    e.scale = vm["scale"].as<double>();
    if (vm.count("sine")) e.sine = parse_sine_spec(vm["sine"].as<std::string>(), "--sine", false);
    if (vm.count("sine-y"))
        e.sine_y = parse_sine_spec(vm["sine-y"].as<std::string>(), "--sine-y", true);
    if (vm.count("motion")) read_motion(vm, e);
    return e;
}


api::SimulateRequest simulate_request(const po::variables_map& vm) {
    api::SimulateRequest r;
    if (three_d(vm)) {
        for (const char* flag : {"cg", "inertia", "top"})
            if (vm.count(flag))
                throw UsageError(fmt::format("--{}: not used by --model 3d", flag));
        r.body3d = body3d_from_options(vm["block"].as<std::string>(), vm["dt"].as<double>());
        r.body3d->phases = vm.count("steps-only") == 0;
    } else {
        if (vm.count("steps-only")) throw UsageError("--steps-only: only with --model 3d");
        r.box = box_from_options(vm["block"].as<std::string>(), opt_string(vm, "cg"),
                                 opt_double(vm, "inertia"));
    }
    r.mu_s = vm["mu"].as<double>();
    r.mu_k = opt_double(vm, "mu-k");
    r.restitution = opt_double(vm, "restitution");
    r.top_height_m = opt_double(vm, "top");
    const std::string integrator = vm["integrator"].as<std::string>();
    const auto named = api::integrator_named(integrator);
    if (!named)
        throw UsageError(fmt::format("--integrator: expected event or cd; got \"{}\"", integrator));
    r.integrator = *named;
    r.cd_dt_s = vm["dt"].as<double>();
    if (vm.count("flexible")) r.flexible = parse_flexible_mode(vm["flexible"].as<std::string>());
    if (pair_requested(vm)) r.unit2 = joined_unit(vm);
    r.excitation = excitation_of(vm);
    r.record_series = vm.count("out") > 0;
    return r;
}

std::string planar_series_csv(const dynamics::SimulationResult& r, const std::string& label) {
    std::string out = fmt::format(
        "# freestand simulate: {} integrator, excitation {}\n"
        "# units: time s, slide m, slide velocity m/s, rotation rad (+ on the right edge), "
        "angular velocity rad/s, forces N (base on block), top corner absolute horizontal "
        "acceleration m/s^2\n"
        "time_s,slide_m,slide_velocity_mps,rotation_rad,angular_velocity_radps,mode,"
        "normal_force_N,friction_force_N,top_accel_mps2\n",
        r.summary.integrator, one_line_label(label));
    for (const auto& s : r.series)
        out += fmt::format("{:.6f},{:.9g},{:.9g},{:.9g},{:.9g},{},{:.9g},{:.9g},{:.9g}\n", s.time_s,
                           s.slide_m, s.slide_velocity_mps, s.rotation_rad,
                           s.angular_velocity_radps, dynamics::to_string(s.mode),
                           s.normal_force_N, s.friction_force_N, s.top_accel_mps2);
    return out;
}

void print_planar(const api::PlanarRun& run) {
    const dynamics::Summary& s = run.result.summary;
    const dynamics::BlockModel& m = run.model;
    std::cout << fmt::format(
        "integrator            {}\n"
        "peak slide            {:.4g} m (residual {:.4g} m)\n"
        "peak rotation         {:.4g} rad = {:.3g} alpha\n"
        "overturned            {}\n"
        "impacts               {} (settled {})\n"
        "mode changes          {}\n"
        "peak top acceleration {:.4g} g = {:.3g} x PGA ({:.4g} g)\n"
        "friction mu_s/mu_k    {} / {}\n"
        "wall time             {:.4g} s\n",
        s.integrator, s.slide_max_m, s.slide_residual_m, s.rock_max_rad, s.rock_max_over_alpha,
        s.overturned ? fmt::format("yes, at {:.4f} s, mode {} ({})", *s.overturn_time_s,
                                   *s.overturn_mode,
                                   dynamics::overturn_criterion_name(s.overturn_criterion))
                     : std::string("no"),
        s.impacts, s.settlements, s.mode_changes, s.top_accel_max_g, s.amplification, s.pga_g,
        m.mu_s, m.mu_k, s.wall_s);
    std::cout << "time in mode         ";
    for (std::size_t i = 0; i < dynamics::mode_count; ++i)
        std::cout << fmt::format(" {} {:.3f} s", dynamics::to_string(static_cast<dynamics::Mode>(i)),
                                 s.time_in_mode_s[i]);
    std::cout << "\n";
}

// The series CSV of the run (a pair records none: require_pair_options refuses --out).
std::string series_csv(const api::SimulateResult& result) {
    const std::string& label = result.excitation_label;
    if (const auto* p = std::get_if<api::PlanarRun>(&result.run))
        return planar_series_csv(p->result, label);
    if (const auto* b = std::get_if<api::BiaxialRun>(&result.run))
        return biaxial_series_csv(*b, label);
    if (const auto* d = std::get_if<api::Body3dRun>(&result.run))
        return body3d_series_csv(*d, label);
    return flexible_series_csv(std::get<api::FlexibleRun>(result.run), label);
}

void print_text(const api::SimulateResult& result) {
    struct Printer {
        void operator()(const api::PlanarRun& r) const { print_planar(r); }
        void operator()(const api::BiaxialRun& r) const { print_biaxial(r); }
        void operator()(const api::FlexibleRun& r) const { print_flexible(r); }
        void operator()(const api::PairRun& r) const { print_pair(r); }
        void operator()(const api::Body3dRun& r) const { print_body3d(r); }
    };
    std::visit(Printer{}, result.run);
}

int run(const std::vector<std::string>& args) {
    const auto vm = parse_options("simulate", usage, simulate_options(), args);
    if (!vm) return 0;
    require_option_set(*vm);
    const api::SimulateResult result = api::simulate(simulate_request(*vm));
    if (vm->count("out"))
        core::write_file_atomic((*vm)["out"].as<std::string>(), series_csv(result));
    if ((*vm)["json"].as<bool>())
        std::cout << api::to_json(result, "--top").dump(2) << "\n";
    else
        print_text(result);
    return 0;
}

const CommandRegistrar reg{{"simulate",
                            "time history of a rigid block (slide, rock, overturn); with "
                            "--motion-y/--sine-y biaxial sliding, --flexible a flexible body, "
                            "--block2 two units joined by a tunnel, --model 3d the rigid body in three dimensions",
                            &run}};

}  // namespace

}  // namespace freestand::cli::simulate_command

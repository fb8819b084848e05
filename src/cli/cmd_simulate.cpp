// `freestand simulate`: rigid-block time history under a record or a sine (src/dynamics).
#include <fmt/format.h>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "cli/documents.hpp"
#include "cli/options.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/printable.hpp"
#include "core/readers.hpp"
#include "core/units.hpp"
#include "cli/simulate_biaxial.hpp"
#include "cli/simulate_pair.hpp"
#include "cli/simulate_flexible.hpp"
#include "dynamics/simulate.hpp"

// The command's own namespace: the command files share a unity build (src/cli/CMakeLists.txt).
namespace freestand::cli::simulate_command {

namespace {

const char* const usage =
    "--block b=0.15,h=0.6,m=38 [--cg x,y] [--inertia I] [--top H] --mu 0.15 [--mu-k MU] "
    "[--restitution R] (--motion FILE[,VERTICAL_FILE] [--motion-y FILE] [--scale S] | "
    "--sine 0.8g,2Hz,5s[,ramp=1s] | --sine-y 0.8g,2Hz,5s[,ramp=1s][,phase=90]) "
    "[--flexible f=HZ[,zeta=Z][,mass=FRACTION][,height=M]] "
    "[--integrator event|cd] [--dt 1e-4] [--out series.csv] [--json] "
    "[--block2 ... [--cg2 ...] --mu2 MU [--mu-k2 MU] [--restitution2 R] --tunnel-height H]";

dynamics::Excitation parse_sine(const std::string& text) {
    return dynamics::sine_excitation(parse_sine_spec(text, "--sine", false));
}

dynamics::Excitation parse_motion(const std::string& text, double scale) {
    const std::vector<std::string> files = split_list(text);
    if (files.size() > 2 || files[0].empty() || (files.size() == 2 && files[1].empty()))
        throw UsageError(fmt::format("--motion: expected FILE[,VERTICAL_FILE]; got \"{}\"", text));
    const core::Record h = core::read_record(files[0]);
    if (files.size() == 1) return dynamics::excitation_from_record(h, scale);
    const core::Record v = core::read_record(files[1]);
    return dynamics::excitation_from_record(h, scale, &v, scale);
}


/// The excitation's label (from a file name) on the CSV's comment line: control characters as
/// \xNN, a line break as a blank, so a file named with ESC or BEL cannot put them raw into the
/// CSV.
std::string one_line_label(const std::string& label) {
    std::string s = core::printable(label);
    for (char& c : s)
        if (c == '\n' || c == '\t') c = ' ';
    return s;
}

std::string series_csv(const dynamics::SimulationResult& r, const std::string& label) {
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
                           s.angular_velocity_radps, dynamics::mode_name(s.mode),
                           s.normal_force_N, s.friction_force_N, s.top_accel_mps2);
    return out;
}

void print_text(const dynamics::Summary& s, const dynamics::BlockModel& m) {
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
        std::cout << fmt::format(" {} {:.3f} s", dynamics::mode_name(static_cast<dynamics::Mode>(i)),
                                 s.time_in_mode_s[i]);
    std::cout << "\n";
}

int run(const std::vector<std::string>& args) {
    po::options_description desc = simulate_model_options();
    desc.add_options()
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
         "defaults zeta 0.02 and a uniform cantilever's 0.613 m at 0.726 x 2 h)")
        ("out", po::value<std::string>(), "write the time series CSV here")
        ("json", po::bool_switch(), "print the summary as JSON");
    add_pair_options(desc);
    const auto vm = parse_options("simulate", usage, desc, args);
    if (!vm) return 0;
    if (vm->count("motion") + vm->count("sine") + vm->count("sine-y") != 1)
        throw UsageError("simulate: give exactly one of --motion, --sine and --sine-y");
    if (vm->count("motion-y") && !vm->count("motion"))
        throw UsageError("--motion-y: needs --motion (the x component)");
    const block::Block blk = simulate_block(*vm);
    const bool biaxial = vm->count("motion-y") || vm->count("sine-y");
    dynamics::Options opt =
        simulate_run_options(*vm, biaxial ? dynamics::biaxial_options() : dynamics::Options{});
    opt.record_series = vm->count("out") > 0;
    if (pair_requested(*vm)) require_pair_options(*vm);
    if (vm->count("flexible") && (biaxial || pair_requested(*vm)))
        throw UsageError("--flexible: runs alone (no --motion-y, --sine-y or second unit)");
    if (biaxial) return run_biaxial_simulation(*vm, blk, opt);
    const dynamics::BlockModel model = simulate_model(*vm, blk);
    const dynamics::Excitation exc =
        vm->count("sine") ? parse_sine((*vm)["sine"].as<std::string>())
                          : parse_motion((*vm)["motion"].as<std::string>(), (*vm)["scale"].as<double>());
    if (pair_requested(*vm)) return run_pair_simulation(*vm, model, exc, opt);
    if (vm->count("flexible")) return run_flexible_simulation(*vm, model, exc, opt);
    const dynamics::SimulationResult res = dynamics::simulate(model, exc, opt);
    if (vm->count("out")) core::write_file_atomic((*vm)["out"].as<std::string>(), series_csv(res, exc.label));
    if ((*vm)["json"].as<bool>()) {
        std::cout << summary_json(res.summary).dump(2) << "\n";
    } else {
        print_text(res.summary, model);
    }
    return 0;
}

const CommandRegistrar reg{{"simulate",
                            "time history of a rigid block (slide, rock, overturn); with "
                            "--motion-y/--sine-y biaxial sliding, --flexible a flexible body, "
                            "--block2 two units joined by a tunnel",
                            &run}};

}  // namespace

}  // namespace freestand::cli::simulate_command

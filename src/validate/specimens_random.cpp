// The random table test of thesis s.3.3.4: TS1-TS3 on steel under a synthetic history of the
// site's design spectrum at 0.8 g, which overturned TS1 and TS2 and left TS3 standing. The
// site's spectrum (Fig. 2-3) and the history are lost: freestand's own spectrum-compatible
// histories stand in for them (docs/methods.md s.8).
#include <fmt/format.h>

#include <algorithm>

#include "assess/body3d_level.hpp"
#include "assess/histories.hpp"
#include "core/measures.hpp"
#include "core/parallel.hpp"
#include "validate/rows.hpp"
#include "validate/specimens.hpp"
#include "validate/thesis.hpp"

namespace freestand::validate {

namespace {

const char* const random_key = "rigid-blocks-random";

double random_pga_g() { return value("ts.random_g"); }

// The thesis saw TS1 and TS2 overturn and TS3 stand (s.3.3.4).
bool thesis_overturned_random(const Specimen& s) { return s.key != "ts3"; }

int overturned_count(const std::vector<dynamics::Summary>& runs) {
    return static_cast<int>(std::count_if(runs.begin(), runs.end(),
                                          [](const dynamics::Summary& r) { return r.overturned; }));
}

std::string standing_text(const std::vector<dynamics::Summary>& runs) {
    double max_rad = 0.0, max_alpha = 0.0;
    for (const dynamics::Summary& r : runs) {
        if (r.overturned) continue;
        max_rad = std::max(max_rad, r.rock_max_rad);
        max_alpha = std::max(max_alpha, r.rock_max_over_alpha);
    }
    return fmt::format("largest peak rotation of the standing runs {} rad = {:.2f} alpha",
                       sig(max_rad), max_alpha);
}

// The specimen as a 3D body: a square footprint (the thesis gives no depth; the shipped TS cases
// take it equal to the width), built as the assessment builds a component's.
dynamics::Body3d specimen_body3d(const Specimen& s) {
    const block::Block blk = specimen_block(s);
    return assess::body3d_of_blocks(blk, blk, s.mass_kg, blk.h_m);
}

int overturned_count(const std::vector<dynamics::Body3dSummary>& runs) {
    return static_cast<int>(std::count_if(
        runs.begin(), runs.end(), [](const dynamics::Body3dSummary& r) { return r.overturned; }));
}

std::string stroke_text(const RandomRuns& runs) {
    return fmt::format(
        "freestand's histories at {:g} g move the ground +-{:.3f} m on average (peak; {:.2f} m "
        "at most), +-{:.3f} m after a {:g} Hz high-pass, against the table's +-{:.3f} m (Table "
        "3-1): the table's motion lacked much of their long-period content, which is what tips "
        "slender blocks",
        random_pga_g(), runs.pgd_mean_m, runs.pgd_max_m, runs.highpass_disp_mean_m,
        runs.highpass_hz, table_stroke_m());
}

Row random_row(const Specimen& s, const std::vector<dynamics::Summary>& runs,
               const std::vector<dynamics::Body3dSummary>& runs3d, const RandomRuns& all) {
    const int n = static_cast<int>(runs.size());
    const int k = overturned_count(runs);
    // One test, many histories: the outcome of most histories is the best estimate of it.
    const bool predicts_overturn = 2 * k > n;
    const bool observed = thesis_overturned_random(s);
    Row row;
    row.group = random_key;
    row.kind = Kind::outcome;
    row.id = fmt::format("{}-random-{:g}g", s.key, random_pga_g());
    row.test = fmt::format("{} on steel, random table motion at {:g} g PGA, horizontal only",
                           s.name, random_pga_g());
    row.thesis = observed ? "overturned" : "stood (sustained the shaking)";
    row.predicted = fmt::format(
        "overturned in {} of {} histories; {}; the 3D body (a square footprint assumed): "
        "overturned in {} of {}",
        k, n, k == n ? "none stood" : standing_text(runs), overturned_count(runs3d),
        runs3d.size());
    row.unit = "fraction of histories";
    row.predicted_value = static_cast<double>(k) / n;
    row.sources = {s.key + ".alpha_rad", s.key + ".R_m",     s.key + ".mass_kg",
                   s.key + ".p_radps",   "steel.mu_s",       "steel.restitution",
                   "ts.random_g",        "ts.random_scaled", "ts.random_outcome",
                   "ts.uniaxial",        "ts.stroke_m"};
    const bool same = predicts_overturn == observed;
    row.difference = same ? "same outcome" : "opposite outcome";
    row.agreement = same ? Agreement::agrees : Agreement::differs;
    row.reason = fmt::format("Not the thesis's motion: {} ({}).", stroke_text(all), all.histories);
    return row;
}

}  // namespace

RandomRuns run_random(const assess::Case& histories_case, const std::string& case_label) {
    assess::HistoryBank bank(histories_case);
    const auto sets = bank.sets();
    RandomRuns out;
    out.histories = fmt::format("the {} RG 1.60 history sets of {}, record h1 scaled to {:g} g",
                                sets.size(), case_label, random_pga_g());
    for (const assess::HistorySet& set : sets) {
        const double pgd_m = core::measure(set.h1).pgd_m * random_pga_g();
        out.pgd_mean_m += pgd_m / static_cast<double>(sets.size());
        out.pgd_max_m = std::max(out.pgd_max_m, pgd_m);
    }
    out.highpass_hz = histories_case.site.energy_highpass_hz;
    out.highpass_disp_mean_m =
        bank.mean_highpass_displacement_m(assess::Direction::x, random_pga_g());
    const std::size_t n_sets = sets.size();
    const std::size_t n_specimens = specimens().size();
    out.runs.assign(n_specimens, std::vector<dynamics::Summary>(n_sets));
    out.runs3d.assign(n_specimens, std::vector<dynamics::Body3dSummary>(n_sets));
    dynamics::Options opt;
    opt.record_series = false;
    opt.g_mps2 = thesis_g_mps2;
    // Each (specimen, history) writes only its own slot: the same result at any thread count.
    core::parallel_for(n_specimens * n_sets, bank.run().threads, [&](std::size_t i) {
        const Specimen& s = specimens()[i / n_sets];
        const assess::HistorySet& set = sets[i % n_sets];
        const dynamics::Excitation x = dynamics::excitation_from_record(set.h1, random_pga_g());
        out.runs[i / n_sets][i % n_sets] =
            dynamics::simulate(specimen_model(s, value("steel.restitution")), x, opt).summary;
        // The table's one component along the body's x axis: the 3D body should repeat the
        // planar block (docs/methods.md s.11 check 3), up to its step.
        const double mu = value("steel.mu_s");
        const auto model = dynamics::make_body3d_model(specimen_body3d(s), mu, mu, 0.0,
                                                       value("steel.restitution"));
        out.runs3d[i / n_sets][i % n_sets] =
            dynamics::simulate_body3d(model,
                                      dynamics::biaxial_excitation(x, std::vector<double>{}),
                                      assess::body3d_options(thesis_g_mps2))
                .summary;
    });
    return out;
}

Group random_group(const RandomRuns& runs) {
    Group g;
    g.key = random_key;
    g.title = "Rigid steel blocks TS1-TS3 under the 0.8 g random table motion (thesis s.3.3.4)";
    g.method =
        "Time-history simulation of the planar rigid block (docs/methods.md s.3, event-driven "
        "integrator) under each of freestand's spectrum-compatible histories (docs/methods.md "
        "s.8) scaled to the test's PGA, the horizontal record only; the 3D rigid body (s.11, "
        "the options of assess) beside it under the same records.";
    g.tolerance =
        "Outcome rows: freestand predicts overturning when more than half of its histories "
        "overturn the block (the thesis ran one history: the outcome of most histories is the "
        "best estimate of one test, not a design fractile).";
    g.assumptions = {
        "the blocks, friction (0.72) and restitution (0.98) of the 0.8 g sine rows",
        "ground motion: " + runs.histories +
            "; the thesis's history (the site's 0.3 g history scaled to 0.8 g) and its spectrum "
            "(Fig. 2-3) are lost",
        "horizontal motion only: the specimens' table is uniaxial (s.3.3.2)",
        "the 3D body: a square footprint (the thesis gives the specimens' width, not their "
        "depth), the planar block's inertia about both horizontal axes",
    };
    return g;
}

std::vector<Row> random_rows(const RandomRuns& runs) {
    std::vector<Row> rows;
    for (std::size_t i = 0; i < specimens().size(); ++i)
        rows.push_back(random_row(specimens()[i], runs.runs[i], runs.runs3d[i], runs));
    return rows;
}

std::string random_note(const RandomRuns& runs) {
    return fmt::format(
        "Random test. The thesis's 0.8 g random motion is lost (s.3.3.4). {}. The random rows "
        "compare outcomes under freestand's histories and count them, but their input is not "
        "the thesis's.",
        stroke_text(runs));
}

}  // namespace freestand::validate

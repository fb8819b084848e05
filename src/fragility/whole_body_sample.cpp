#include "assess/body3d_level.hpp"
#include "dynamics/biaxial.hpp"
#include "dynamics/body3d.hpp"
#include "fragility/runner_detail.hpp"

namespace freestand::fragility {

std::optional<WholeBody> whole_body_sample(const assess::Case& c, const assess::HistorySet& set,
                                           double pga_g, double mu_s, double mu_k,
                                           double restitution, const Models& models,
                                           bool flexible) {
    const dynamics::BiaxialExcitation ex =
        dynamics::biaxial_excitation_from_records(set.h1, set.h2, pga_g, &set.v);
    const dynamics::BiaxialModel sliding = dynamics::make_biaxial_model(mu_s, mu_k);
    bool rocks = false;
    for (const assess::Direction d : {assess::Direction::x, assess::Direction::y})
        rocks = rocks || dynamics::biaxial_rocking_reason(c.component.block(d), sliding, ex,
                                                          c.site.g_mps2)
                             .has_value();
    WholeBody out;
    if (rocks) {
        if (!models.body3d) return std::nullopt;
        dynamics::Body3dModel model =
            dynamics::make_body3d_model(assess::component_body3d(c.component), mu_s, mu_k, 0.0,
                                        restitution);
        if (flexible)
            model = dynamics::with_mode(
                model, assess::body3d_mode(c.component,
                                           {mu_s, mu_k, restitution, false, ""}));
        const dynamics::Body3dSummary s =
            dynamics::simulate_body3d(model, ex, assess::body3d_options(c.site.g_mps2)).summary;
        out.model = WholeBody::Model::body3d;
        // A body that tips over carries its footprint centre with it: the overturn is the event.
        out.slide_max_m = s.overturned ? 0.0 : s.slide_max_m;
        out.rock_max_over_alpha = s.tilt_max_over_critical;
        out.overturned = s.overturned;
        return out;
    }
    if (!models.biaxial_slide) return std::nullopt;
    dynamics::Options opt = dynamics::biaxial_options();
    opt.record_series = false;
    opt.g_mps2 = c.site.g_mps2;
    out.slide_max_m = dynamics::simulate_biaxial(sliding, ex, opt).summary.slide_max_m;
    return out;
}

}  // namespace freestand::fragility

#include "dynamics/biaxial.hpp"
#include "fragility/runner_detail.hpp"

namespace freestand::fragility {

std::optional<double> biaxial_slide_m(const assess::Case& c, const assess::HistorySet& set,
                                      double pga_g, double mu_s, double mu_k) {
    const dynamics::BiaxialModel model = dynamics::make_biaxial_model(mu_s, mu_k);
    const dynamics::BiaxialExcitation ex =
        dynamics::biaxial_excitation_from_records(set.h1, set.h2, pga_g, &set.v);
    for (const assess::Direction d : {assess::Direction::x, assess::Direction::y})
        if (dynamics::biaxial_rocking_reason(c.component.block(d), model, ex, c.site.g_mps2))
            return std::nullopt;
    dynamics::Options opt = dynamics::biaxial_options();
    opt.record_series = false;
    opt.g_mps2 = c.site.g_mps2;
    return dynamics::simulate_biaxial(model, ex, opt).summary.slide_max_m;
}

}  // namespace freestand::fragility

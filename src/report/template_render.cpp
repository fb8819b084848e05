#include "report/template_render.hpp"

#include "report/escape_guard.hpp"
#include "report/escape.hpp"

namespace freestand::report {

extern const char* const template_print_style_html;

std::string render_markdown(const std::string& tpl, const mstch::map& ctx,
                            const Partials& partials) {
    EscapeGuard guard(markdown_escape);
    return mstch::render(tpl, ctx, partials);
}

std::string render_html(const std::string& tpl, const mstch::map& ctx, const Partials& partials) {
    EscapeGuard guard(html_escape);
    Partials with_print = partials;
    with_print.emplace("print_style", template_print_style_html);
    return mstch::render(tpl, ctx, with_print);
}

mstch::array stamp_input_items(const Stamp& stamp) {
    mstch::array out;
    for (const StampedInput& i : stamp.inputs)
        out.push_back(mstch::map{{"file", i.file}, {"sha256", i.sha256}});
    return out;
}

mstch::array text_list(const std::vector<std::string>& items) {
    mstch::array out;
    for (const std::string& s : items) out.push_back(mstch::map{{"text", s}});
    return out;
}

mstch::array reference_items(const std::vector<Reference>& refs) {
    mstch::array out;
    for (const Reference& r : refs) out.push_back(mstch::map{{"key", r.key}, {"text", r.text}});
    return out;
}

}  // namespace freestand::report

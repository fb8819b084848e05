#pragma once
/// What every report renderer shares: rendering a compiled-in mustache template with Markdown
/// or HTML escaping, and the template items of the stamp's inputs and of a reference list.
#include <map>
#include <string>
#include <vector>

#include <mstch/mstch.hpp>

#include "report/json.hpp"
#include "report/references.hpp"

namespace freestand::report {

/// Partial templates by name ({{> name}}).
using Partials = std::map<std::string, std::string>;

/// The template rendered with every {{value}} Markdown-escaped (markdown_escape).
std::string render_markdown(const std::string& tpl, const mstch::map& ctx,
                            const Partials& partials = {});

/// The template rendered with every {{value}} HTML-escaped (html_escape). Every HTML template
/// may include {{> print_style}}, the print CSS the reports share (templates/
/// print_style.html.mustache: pages, page numbers, repeated table headers).
std::string render_html(const std::string& tpl, const mstch::map& ctx,
                        const Partials& partials = {});

/// [{"file", "sha256"}] of the stamp's other inputs.
mstch::array stamp_input_items(const Stamp& stamp);

/// [{"text"}] of the lines, in order.
mstch::array text_list(const std::vector<std::string>& items);

/// [{"key", "text"}] of the references.
mstch::array reference_items(const std::vector<Reference>& refs);

}  // namespace freestand::report

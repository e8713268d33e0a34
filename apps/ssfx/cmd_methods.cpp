// ssfx methods: every family's registry as a table or JSON (ids, summaries, inputs,
// backends, presets, parameters with defaults, ranges and docs).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <nlohmann/json.hpp>
#include <vector>

#include "commands.hpp"
#include "ssfx/ao/registry.hpp"
#include "ssfx/core/error.hpp"
#include "ssfx/registry.hpp"
#ifdef SSFX_HAVE_RENDER
#include "ssfx/deferred/registry.hpp"
#endif

namespace ssfx::cli {

namespace {

// Every registered method of every family built into this ssfx, in kFamilies' order.
std::vector<const MethodDesc*> allMethods() {
    std::vector<const MethodDesc*> all;
    for (const MethodInfo& m : methods()) all.push_back(&m);
    for (const ao::AoMethodInfo& m : ao::aoMethods()) all.push_back(&m);
#ifdef SSFX_HAVE_RENDER
    for (const deferred::DeferredMethodInfo& m : deferred::deferredMethods()) all.push_back(&m);
#endif
    return all;
}

nlohmann::ordered_json toJson(const MethodDesc& m) {
    nlohmann::ordered_json j;
    j["id"] = m.id, j["family"] = m.family, j["summary"] = m.summary, j["citation"] = m.citation;
    j["inputs"] = m.inputs;
    j["backends"] = std::vector<std::string>(m.backends.begin(), m.backends.end());
    j["presets"] = std::vector<std::string>(m.presets.begin(), m.presets.end());
    j["params"] = nlohmann::ordered_json::array();
    for (const ParamInfo& p : m.params) {
        nlohmann::ordered_json r;
        r["name"] = p.name, r["kind"] = kindName(p.kind), r["unit"] = p.unit;
        if (p.kind == ParamKind::Choice) {
            r["default"] = p.valueText(p.defaultValue());
            r["choices"] = std::vector<std::string>(p.choices.begin(), p.choices.end());
        } else {
            // A float member's default as the shortest decimal that names it (0.166, not 0.165999...).
            r["default"] = p.kind == ParamKind::Real ? nlohmann::ordered_json(std::stod(p.valueText(p.defaultValue())))
                                                    : nlohmann::ordered_json(std::int64_t(p.defaultValue()));
            r["min"] = p.min, r["max"] = p.max;
        }
        r["doc"] = p.doc;
        j["params"].push_back(r);
    }
    return j;
}

void printText(const MethodDesc& m) {
    fmt::print("{:<12} {:<9} {:<8} {}\n", m.id, m.family, fmt::format("{}", fmt::join(m.backends, ",")), m.summary);
    std::string notes = fmt::format("input: {}", m.inputs);
    if (!m.presets.empty()) notes += fmt::format("; presets: {} (the first is the default)", fmt::join(m.presets, ", "));
    if (!m.citation.empty()) notes += "; " + std::string(m.citation);
    fmt::print("             {}\n", notes);
    for (const ParamInfo& p : m.params)
        fmt::print("             -p {}={:<8} {}{}{}  {}\n", p.name, p.valueText(p.defaultValue()), p.rangeText(),
                   p.unit.empty() ? "" : " ", p.unit, p.doc);
}

}  // namespace

void addMethodsCommand(CLI::App& app) {
    auto* cmd = app.add_subcommand("methods", "List every method (aa, ao, deferred) with its backends and parameters");
    auto idsOnly = std::make_shared<bool>(false);
    auto json = std::make_shared<bool>(false);
    auto family = std::make_shared<std::string>();
    cmd->add_flag("--ids", *idsOnly, "Print only the method ids, one per line");
    cmd->add_flag("--json", *json, "Print JSON: an array of methods with their parameters (kind, unit, default, range)");
    cmd->add_option("--family", *family, fmt::format("Only one family: {}", fmt::join(kFamilies, ", ")));
    cmd->footer("Columns: id, family, backends, summary; then the inputs, presets, citation and each -p parameter\n"
                "with its default, range (or choices) and unit. The tables are the params structs' own\n"
                "(include/ssfx/*/...: one declaration per parameter).");
    cmd->callback([idsOnly, json, family] {
        bool known = family->empty();
        for (const std::string_view f : kFamilies) known = known || f == *family;
        if (!known) throw Error(fmt::format("--family '{}' is not one of {}", *family, fmt::join(kFamilies, ", ")));
        nlohmann::ordered_json all = nlohmann::ordered_json::array();
        for (const MethodDesc* m : allMethods()) {
            if (!family->empty() && m->family != *family) continue;
            if (*json) all.push_back(toJson(*m));
            else if (*idsOnly) fmt::print("{}\n", m->id);
            else printText(*m);
        }
        if (*json) fmt::print("{}\n", all.dump(2));
    });
}

}  // namespace ssfx::cli

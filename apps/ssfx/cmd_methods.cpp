// ssfx methods: the registry as a table (ids, summaries, parameters with defaults and ranges).
#include <fmt/format.h>

#include "commands.hpp"
#include "ssfx/registry.hpp"

namespace ssfx::cli {

void addMethodsCommand(CLI::App& app) {
    auto* cmd = app.add_subcommand("methods", "List the methods with their parameters and defaults");
    auto idsOnly = std::make_shared<bool>(false);
    cmd->add_flag("--ids", *idsOnly, "Print only the method ids, one per line");
    cmd->callback([idsOnly] {
        for (const MethodInfo& m : methods()) {
            if (*idsOnly) {
                fmt::print("{}\n", m.id);
                continue;
            }
            fmt::print("{:<8} {}\n", m.id, m.summary);
            std::string notes;
            if (m.inputScale != 1) notes += fmt::format("input: the {}x render; ", m.inputScale);
            if (m.usesPresets) notes += "presets: low, medium (default), high, ultra, extreme; ";
            if (!m.citation.empty()) notes += m.citation;
            if (!notes.empty()) fmt::print("         {}\n", notes);
            for (const ParamInfo& p : m.params)
                fmt::print("         -p {}={:<8} {}{}{}  {}\n", p.name, p.valueText(p.defaultValue()), p.rangeText(),
                           p.unit.empty() ? "" : " ", p.unit, p.doc);
        }
    });
}

}  // namespace ssfx::cli

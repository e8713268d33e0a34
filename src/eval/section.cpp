// Report sections as data, and their Markdown (see section.hpp).
#include "ssfx/eval/section.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace ssfx::eval {

Table numericTable(const std::string& corner, const std::vector<std::string>& rowNames,
                   const std::vector<std::string>& columns, const std::vector<std::vector<double>>& values,
                   int decimals, bool higherIsBetter) {
    Table t;
    t.header.push_back(corner);
    t.header.insert(t.header.end(), columns.begin(), columns.end());
    for (std::size_t r = 0; r < rowNames.size(); ++r) {
        double best = higherIsBetter ? -INFINITY : INFINITY;
        for (double v : values[r])
            if (!std::isnan(v)) best = higherIsBetter ? std::max(best, v) : std::min(best, v);
        std::vector<std::string> row{rowNames[r]};
        std::vector<bool> bold{false};
        for (double v : values[r]) {
            row.push_back(std::isnan(v) ? "-" : std::isinf(v) ? "inf" : fmt::format("{:.{}f}", v, decimals));
            bold.push_back(v == best);
        }
        t.rows.push_back(std::move(row));
        t.best.push_back(std::move(bold));
    }
    return t;
}

namespace {

std::string markdownRow(const std::vector<std::string>& cells) {
    std::string s = "|";
    for (const auto& c : cells) s += fmt::format(" {} |", c);
    return s + "\n";
}

}  // namespace

std::string markdown(const Table& table) {
    std::string s = markdownRow(table.header) + "|---|";
    for (std::size_t i = 1; i < table.header.size(); ++i) s += "---:|";
    s += "\n";
    for (const auto& row : table.rows) s += markdownRow(row);
    return s;
}

std::string markdown(const Section& section) {
    std::string s;
    for (std::size_t i = 0; i < section.blocks.size(); ++i) {
        const Block& b = section.blocks[i];
        if (i > 0) s += "\n";
        s += fmt::format("### {}\n\n", b.heading);
        if (!b.text.empty()) s += b.text + "\n\n";
        if (!b.table.header.empty()) s += markdown(b.table);
        if (!b.after.empty()) s += "\n" + b.after + "\n";
    }
    return s;
}

void prefixPaths(Section& section, const std::string& dir) {
    for (Block& b : section.blocks) {
        for (Figure& f : b.figures) f.path = dir + "/" + f.path;
        for (Viewer& v : b.viewers)
            for (auto& [label, path] : v.sources) path = dir + "/" + path;
    }
}

}  // namespace ssfx::eval

// See params.hpp.
#include "ssfx/core/params.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

#include "ssfx/core/error.hpp"

namespace ssfx {

std::string_view kindName(ParamKind kind) {
    switch (kind) {
        case ParamKind::Real: return "real";
        case ParamKind::Integer: return "integer";
        case ParamKind::Boolean: return "boolean";
        case ParamKind::Choice: return "choice";
    }
    return "?";
}

std::string ParamInfo::valueText(double value) const {
    if (kind == ParamKind::Choice && value >= 0 && value < double(choices.size()) && value == std::floor(value))
        return std::string(choices[std::size_t(value)]);
    return fmt::format("{:g}", value);
}

std::string ParamInfo::rangeText() const {
    if (kind == ParamKind::Boolean) return "0|1";
    if (kind == ParamKind::Choice) return fmt::format("{}", fmt::join(choices, "|"));
    return fmt::format("[{:g}, {:g}]", min, max);
}

const ParamInfo& findParam(std::span<const ParamInfo> table, std::string_view id, std::string_view name) {
    for (const ParamInfo& row : table)
        if (row.name == name) return row;
    std::string known;
    for (const ParamInfo& row : table) known += fmt::format("{}{}", known.empty() ? "" : ", ", row.name);
    throw Error(fmt::format("{}: unknown parameter '{}' (parameters: {})", id, name, known.empty() ? "none" : known));
}

void checkParam(const ParamInfo& row, double v, std::string_view id) {
    switch (row.kind) {
        case ParamKind::Real:
            if (!(v >= row.min && v <= row.max))
                throw Error(fmt::format("{}: {} = {} is not in [{}, {}]", id, row.name, v, row.min, row.max));
            return;
        case ParamKind::Integer:
            if (!(v >= row.min && v <= row.max && v == std::floor(v)))
                throw Error(
                    fmt::format("{}: {} = {} is not an integer in [{}, {}]", id, row.name, v, row.min, row.max));
            return;
        case ParamKind::Boolean:
            if (v != 0.0 && v != 1.0) throw Error(fmt::format("{}: {} = {} is not 0 or 1", id, row.name, v));
            return;
        case ParamKind::Choice:
            if (!(v >= 0 && v < double(row.choices.size()) && v == std::floor(v)))
                throw Error(fmt::format("{}: {} = {} is not one of {}", id, row.name, v, fmt::join(row.choices, ", ")));
            return;
    }
}

void setParam(std::span<const ParamInfo> table, void* params, std::string_view id, std::string_view name, double v) {
    const ParamInfo& row = findParam(table, id, name);
    if (row.kind == ParamKind::Real) {
        // Checked as the member stores it (float(v) for a float), as validateParams sees it:
        // the library and the CLI accept exactly the same values.
        row.set(params, v);
        checkParam(row, row.get(params), id);
        return;
    }
    checkParam(row, v, id);  // before the cast: an integer is never rounded or wrapped
    row.set(params, v);
}

double parseParamValue(const ParamInfo& row, std::string_view text, std::string_view id) {
    if (row.kind == ParamKind::Boolean) {
        if (text == "true") return 1.0;
        if (text == "false") return 0.0;
    }
    if (row.kind == ParamKind::Choice)
        for (std::size_t i = 0; i < row.choices.size(); ++i)
            if (row.choices[i] == text) return double(i);
    double v = 0;
    // An explicit plus sign is a number too (from_chars takes only '-').
    const std::size_t skip = text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+' ? 1 : 0;
    const auto [end, ec] = std::from_chars(text.data() + skip, text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || text.empty()) {
        if (row.kind == ParamKind::Choice)
            throw Error(
                fmt::format("{}: {} = '{}' is not one of {}", id, row.name, text, fmt::join(row.choices, ", ")));
        throw Error(fmt::format("{}: {} = '{}' is not a number{}", id, row.name, text,
                                row.kind == ParamKind::Boolean ? " (or true, false)" : ""));
    }
    return v;
}

void validateParams(std::span<const ParamInfo> table, const void* params, std::string_view id) {
    for (const ParamInfo& row : table) checkParam(row, row.get(params), id);
}

}  // namespace ssfx

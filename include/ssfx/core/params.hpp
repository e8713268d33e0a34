// One declaration per parameter (STYLE.md section 2). Beside each params struct, one table
// of ParamInfo rows (name, kind, unit, range, doc, and the member it binds); validation,
// `-p NAME=VALUE` parsing, --help, `ssfx methods` and the docs' parameter lists are derived
// from the tables. A row's default is read from the struct's own initialiser, so it cannot
// disagree with the struct.
//
//   struct BlurParams { float sigma = 0.6f; };
//   inline constexpr std::array kBlurParams{
//       real<&BlurParams::sigma>("sigma", "px", 0.05, 10, "Gaussian sigma")};
//
// Nested members are paths: integer<&SaoParams::blur, &BilateralParams::blurRadius>(...).
#pragma once

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

namespace ssfx {

//! Real: any value in [min, max] (stored in the member's type, checked as stored);
//! Integer: a whole number in [min, max], never rounded; Boolean: 0 or 1 (true, false);
//! Choice: one of `choices` by name (or its index), stored as the enum value of that index.
enum class ParamKind { Real, Integer, Boolean, Choice };
std::string_view kindName(ParamKind kind);

struct ParamInfo {
    std::string_view name;  //!< the member's name (the paper's)
    ParamKind kind;
    std::string_view unit;  //!< "m", "px", "luma", ... or empty
    double min, max;        //!< inclusive; Boolean [0, 1]; Choice [0, choices - 1]
    std::string_view doc;
    std::span<const std::string_view> choices;  //!< Choice: the names of 0, 1, ...
    double (*get)(const void* params);          //!< the member of a params struct, as a number
    void (*set)(void* params, double value);    //!< no checks: see setParam
    double (*initial)();                        //!< the member in a default-constructed struct

    double defaultValue() const { return initial(); }
    //! "0.6", "5", "1", "rotated-grid": a value as `-p` takes it.
    std::string valueText(double value) const;
    //! "[0.05, 10]", "0|1", "a|b|c": the allowed values.
    std::string rangeText() const;
};

//! The row called `name`; throws ssfx::Error "ID: unknown parameter 'NAME' (parameters: ...)".
const ParamInfo& findParam(std::span<const ParamInfo> table, std::string_view id, std::string_view name);

//! The one range check. Throws ssfx::Error "ID: NAME = V is not in [MIN, MAX]" (a Real,
//! also for NaN), "... is not an integer in [MIN, MAX]", "... is not 0 or 1",
//! "... is not one of a, b".
void checkParam(const ParamInfo& row, double value, std::string_view id);

//! Checks `value` (a Real as the member stores it: float(value) for a float member) and sets
//! the member. `params` is the struct the table describes.
void setParam(std::span<const ParamInfo> table, void* params, std::string_view id, std::string_view name, double value);

//! Parses `text` for the row: a number (strict: "1e-3", "+1"; not "1x", "", "0x10"), for a
//! Boolean also true/false, for a Choice a name (or its index). Throws ssfx::Error naming ID
//! and NAME. The value is not range-checked here.
double parseParamValue(const ParamInfo& row, std::string_view text, std::string_view id);

//! Every row of `table` checked on `params` (a struct filled in by a library caller).
void validateParams(std::span<const ParamInfo> table, const void* params, std::string_view id);

namespace detail {

template <class M>
struct MemberClass;
template <class C, class T>
struct MemberClass<T C::*> {
    using type = C;
};

template <class T>
double toNumber(const T& v) {
    if constexpr (std::is_enum_v<T>)
        return double(static_cast<std::underlying_type_t<T>>(v));
    else
        return double(v);
}
template <class T>
T fromNumber(double v) {
    if constexpr (std::is_enum_v<T>)
        return static_cast<T>(static_cast<std::underlying_type_t<T>>(v));
    else if constexpr (std::is_same_v<T, bool>)
        return v != 0.0;
    else
        return static_cast<T>(v);
}

//! The member reached from an Owner by Path (a chain of member pointers; the first may be
//! a member of a base class of Owner).
template <class Owner, auto First, auto... Rest>
struct Field {
    using P = Owner;
    static auto& ref(P& p) { return ((p.*First).*....*Rest); }
    static const auto& cref(const P& p) { return ((p.*First).*....*Rest); }
    using T = std::remove_cvref_t<decltype(cref(std::declval<const P&>()))>;
    static double get(const void* p) { return toNumber(cref(*static_cast<const P*>(p))); }
    static void set(void* p, double v) { ref(*static_cast<P*>(p)) = fromNumber<T>(v); }
    static double initial() {
        const P defaults{};
        return toNumber(cref(defaults));
    }
};

}  // namespace detail

template <class Owner, auto... Path>
constexpr ParamInfo realIn(std::string_view name, std::string_view unit, double min, double max, std::string_view doc) {
    using F = detail::Field<Owner, Path...>;
    static_assert(std::is_floating_point_v<typename F::T>, "real(): the member is not a float or double");
    return {name, ParamKind::Real, unit, min, max, doc, {}, &F::get, &F::set, &F::initial};
}
//! A Real row; realIn<Derived, &Base::member> binds a base class's member for a derived struct.
template <auto First, auto... Rest>
constexpr ParamInfo real(std::string_view name, std::string_view unit, double min, double max, std::string_view doc) {
    return realIn<typename detail::MemberClass<decltype(First)>::type, First, Rest...>(name, unit, min, max, doc);
}
template <auto First, auto... Rest>
constexpr ParamInfo integer(std::string_view name, std::string_view unit, double min, double max,
                            std::string_view doc) {
    using F = detail::Field<typename detail::MemberClass<decltype(First)>::type, First, Rest...>;
    static_assert(std::is_integral_v<typename F::T> && !std::is_same_v<typename F::T, bool>,
                  "integer(): the member is not an integer");
    return {name, ParamKind::Integer, unit, min, max, doc, {}, &F::get, &F::set, &F::initial};
}
template <auto First, auto... Rest>
constexpr ParamInfo boolean(std::string_view name, std::string_view doc) {
    using F = detail::Field<typename detail::MemberClass<decltype(First)>::type, First, Rest...>;
    static_assert(std::is_same_v<typename F::T, bool>, "boolean(): the member is not a bool");
    return {name, ParamKind::Boolean, "", 0, 1, doc, {}, &F::get, &F::set, &F::initial};
}
template <class Owner, auto... Path>
constexpr ParamInfo choiceIn(std::string_view name, std::span<const std::string_view> names, std::string_view doc) {
    using F = detail::Field<Owner, Path...>;
    static_assert(std::is_enum_v<typename F::T>, "choice(): the member is not an enum");
    return {name, ParamKind::Choice, "", 0, double(names.size()) - 1, doc, names, &F::get, &F::set, &F::initial};
}
//! A Choice row; choiceIn<Derived, &Base::member> binds a base class's member for a derived struct.
template <auto First, auto... Rest>
constexpr ParamInfo choice(std::string_view name, std::span<const std::string_view> names, std::string_view doc) {
    return choiceIn<typename detail::MemberClass<decltype(First)>::type, First, Rest...>(name, names, doc);
}

//! Two tables as one (a method's own rows, then shared ones).
template <std::size_t A, std::size_t B>
constexpr std::array<ParamInfo, A + B> concat(const std::array<ParamInfo, A>& a, const std::array<ParamInfo, B>& b) {
    std::array<ParamInfo, A + B> out{};
    for (std::size_t i = 0; i < A; ++i) out[i] = a[i];
    for (std::size_t i = 0; i < B; ++i) out[A + i] = b[i];
    return out;
}

}  // namespace ssfx

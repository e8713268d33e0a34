// Checks every parameter table the same way (tests/core/test_params.cpp for aa and ao,
// tests/deferred for deferred): well-formed rows, defaults inside their ranges, and the two
// ways in, setParam (what -p and every registry use) and a library caller's struct checked by
// the method's own validation, accepting and rejecting exactly the same values.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "ssfx/core/error.hpp"
#include "ssfx/core/params.hpp"

namespace ssfx::test {

//! `needs` sets, before a row is probed, the other fields that row's rules across fields
//! depend on (SaoParams::releasedPacking needs packBlurInput), on both structs alike.
template <class P>
void checkParamTable(std::span<const ParamInfo> table, std::string_view id,
                     const std::function<void(const P&)>& validate,
                     const std::function<void(P&, std::string_view)>& needs = {}) {
    SCOPED_TRACE(std::string(id));
    ASSERT_FALSE(table.empty());
    std::set<std::string_view> names;
    const P defaults{};
    EXPECT_NO_THROW(validate(defaults)) << "the defaults must be valid";
    for (const ParamInfo& row : table) {
        SCOPED_TRACE(std::string(row.name));
        EXPECT_TRUE(names.insert(row.name).second) << "duplicate name";
        EXPECT_FALSE(row.doc.empty());
        EXPECT_LE(row.min, row.max);
        EXPECT_EQ(row.get(&defaults), row.defaultValue());
        EXPECT_NO_THROW(checkParam(row, row.defaultValue(), id))
            << "default " << row.defaultValue() << " outside " << row.rangeText();
        if (row.kind == ParamKind::Boolean) {
            EXPECT_TRUE(row.min == 0 && row.max == 1);
        }
        if (row.kind == ParamKind::Choice) {
            EXPECT_EQ(row.max, double(row.choices.size()) - 1);
        }
        const double inf = std::numeric_limits<double>::infinity();
        const double span = std::max(1.0, row.max - row.min);
        std::vector<double> probes = {row.min,
                                      row.max,
                                      (row.min + row.max) / 2,
                                      row.min - span * 1e-3,
                                      row.max + span * 1e-3,
                                      row.min - 1,
                                      row.max + 1,
                                      std::nan(""),
                                      inf,
                                      -inf,
                                      4294967297.0,
                                      -2147483649.0,
                                      std::floor(row.min) + 0.5};
        for (const double v : probes) {
            SCOPED_TRACE(v);
            P viaTable = defaults;
            if (needs) needs(viaTable, row.name);
            bool tableOk = true;
            try {
                setParam(table, &viaTable, id, row.name, v);
            } catch (const Error& e) {
                tableOk = false;
                EXPECT_NE(std::string(e.what()).find(std::string(row.name)), std::string::npos) << e.what();
            }
            // A library caller can only store what the member's type holds: an integer, a
            // bool or an enum value that is a whole number in range of the type.
            const bool storable =
                row.kind == ParamKind::Real || (std::isfinite(v) && v == std::floor(v) && std::abs(v) < 2147483647.0 &&
                                                (row.kind != ParamKind::Boolean || v == 0 || v == 1) &&
                                                (row.kind != ParamKind::Choice || (v >= 0 && v < 256)));
            if (!storable) {
                EXPECT_FALSE(tableOk) << "setParam took a value no member can hold";
                continue;
            }
            P direct = defaults;
            if (needs) needs(direct, row.name);
            row.set(&direct, v);
            bool directOk = true;
            try {
                validate(direct);
            } catch (const Error&) {
                directOk = false;
            }
            // What the table takes, the method takes, and back.
            EXPECT_EQ(tableOk, directOk) << "setParam " << (tableOk ? "accepts" : "rejects") << " but the method "
                                         << (directOk ? "accepts" : "rejects");
            if (tableOk) {
                EXPECT_EQ(row.get(&viaTable), row.get(&direct));
            }
        }
    }
}

}  // namespace ssfx::test

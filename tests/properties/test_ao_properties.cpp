// Properties every registered AO method must have, through the AO registry (new methods are
// covered automatically): the same bytes for any thread count, every parameter outside its
// range refused, NaN depth refused with an error naming it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "ssfx/ao/registry.hpp"
#include "ssfx/core/error.hpp"
#include "ssfx/scene/analytic.hpp"

using namespace ssfx;

namespace {

class AoProperty : public ::testing::TestWithParam<const ao::AoMethodInfo*> {};

std::string name(const ::testing::TestParamInfo<const ao::AoMethodInfo*>& i) { return std::string(i.param->id); }

std::vector<const ao::AoMethodInfo*> all() {
    std::vector<const ao::AoMethodInfo*> v;
    for (const auto& m : ao::aoMethods()) v.push_back(&m);
    return v;
}

// The analytic room: its depth buffer, and the room itself for the ray-traced truth.
struct Room {
    scene::AnalyticScene scene = scene::analyticSceneByName("room");
    Camera camera;
    ImageF depth;
    Room(int w, int h) { depth = scene::castGeometry(scene, camera, w, h, Exec{1}).depth; }
    ao::AoInput input() const { return {depth.view(), camera, &scene, {}, {}}; }
};

ao::AoParams small(const ao::AoMethodInfo& m) {
    ao::AoParams p = m.defaults("");
    if (m.needsGeometry) ao::setParam(m, p, "raysPerPixel", 8);  // the property, not the noise
    return p;
}

bool sameBytes(const ImageF& a, const ImageF& b) {
    return a.width() == b.width() && a.height() == b.height() &&
           std::memcmp(a.data(), b.data(), std::size_t(a.width()) * std::size_t(a.height()) * sizeof(float)) == 0;
}

}  // namespace

TEST_P(AoProperty, SameBytesForAnyThreadCount) {
    const ao::AoMethodInfo& m = *GetParam();
    const Room room(96, 70);  // 70 rows: several row blocks
    const ao::AoParams p = small(m);
    const ImageF one = m.run(room.input(), p, Exec{1});
    EXPECT_TRUE(sameBytes(m.run(room.input(), p, Exec{2}), one));
    EXPECT_TRUE(sameBytes(m.run(room.input(), p, Exec{8}), one));
    // And something was computed: the room's corners are occluded.
    float lo = 1;
    for (int y = 0; y < one.height(); ++y)
        for (int x = 0; x < one.width(); ++x) lo = std::min(lo, one(x, y));
    EXPECT_LT(lo, 0.9f);
}

TEST_P(AoProperty, EveryParameterOutsideItsRangeIsRefused) {
    const ao::AoMethodInfo& m = *GetParam();
    for (const ParamInfo& row : m.params) {
        ao::AoParams p = m.defaults("");
        const double step = std::max(1.0, std::abs(row.max) * 1e-3);  // beyond a float's rounding
        for (const double bad : {row.max + step, row.min - step, std::nan("")}) {
            EXPECT_THROW(ao::setParam(m, p, row.name, bad), Error) << m.id << " " << row.name << " = " << bad;
            // A library caller's struct with the bad value is refused by the method too.
            ao::AoParams direct = m.defaults("");
            std::visit([&](auto& v) { row.set(&v, bad); }, direct);
            if (row.kind == ParamKind::Real) {
                EXPECT_THROW(m.validate(direct), Error) << m.id << " " << row.name;
            }
        }
    }
}

// The methods that read the depth values (not raytraced, which reads the geometry).
class AoDepthProperty : public AoProperty {};

TEST_P(AoDepthProperty, NanDepthIsRefused) {
    const ao::AoMethodInfo& m = *GetParam();
    Room room(32, 24);
    room.depth(5, 7) = std::nanf("");
    try {
        m.run(room.input(), small(m), Exec{1});
        ADD_FAILURE() << m.id << " accepted a NaN depth";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("(5, 7)"), std::string::npos) << e.what();
    }
}

TEST(AoRegistry, IdsPresetsAndErrors) {
    std::vector<std::string> ids;
    for (const auto& m : ao::aoMethods()) ids.emplace_back(m.id);
    EXPECT_EQ(ids, (std::vector<std::string>{"sao", "alchemy", "gtao", "raytraced"}));
    EXPECT_THROW(ao::aoMethodById("hbao"), Error);
    const auto& sao = ao::aoMethodById("sao");
    EXPECT_EQ(std::get<ao::SaoParams>(sao.defaults("released")).numSamples, 11);
    EXPECT_THROW(sao.defaults("nope"), Error);
    EXPECT_THROW(ao::aoMethodById("alchemy").defaults("released"), Error);
    // GTAO's presets are the spec's quality levels (gtao.md section 10).
    const auto& gtao = ao::aoMethodById("gtao");
    EXPECT_EQ(std::get<ao::GtaoParams>(gtao.defaults("low")).sliceCount, 1);
    EXPECT_EQ(std::get<ao::GtaoParams>(gtao.defaults("ultra")).sliceCount, 9);
    EXPECT_THROW(gtao.defaults("extreme"), Error);
    // Parameters of one method are not another's.
    ao::AoParams p = ao::aoMethodById("alchemy").defaults("");
    EXPECT_THROW(ao::setParam(sao, p, "radius", 1), Error);
    EXPECT_THROW(sao.validate(p), Error);
    // The ray-traced truth without geometry: an error, not a crash.
    const auto& rt = ao::aoMethodById("raytraced");
    ImageF depth(8, 8);
    EXPECT_THROW(rt.run({depth.view(), Camera{}, nullptr, {}, {}}, rt.defaults(""), Exec{1}), Error);
}

INSTANTIATE_TEST_SUITE_P(All, AoProperty, ::testing::ValuesIn(all()), name);

std::vector<const ao::AoMethodInfo*> readingDepth() {
    std::vector<const ao::AoMethodInfo*> v;
    for (const ao::AoMethodInfo* m : all())
        if (!m->needsGeometry) v.push_back(m);
    return v;
}
INSTANTIATE_TEST_SUITE_P(All, AoDepthProperty, ::testing::ValuesIn(readingDepth()), name);

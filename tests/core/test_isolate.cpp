// runIsolated: the child's bytes come back; its ssfx::Error comes back with its message; a
// child that dies (abort, a null dereference) is an ssfx::Error naming what was being done.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <string>

#include "ssfx/core/error.hpp"
#include "ssfx/core/isolate.hpp"
#include "ssfx/core/parallel.hpp"

namespace ssfx::test {
namespace {

std::string errorOf(const std::function<std::vector<std::uint8_t>()>& work) {
    try {
        runIsolated(work, "model 'x'", "parser");
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(Isolate, ReturnsTheChildsBytes) {
    std::vector<std::uint8_t> big(5'000'000);
    for (std::size_t i = 0; i < big.size(); ++i) big[i] = std::uint8_t(i * 7 + 3);
    EXPECT_EQ(runIsolated([&] { return big; }, "x", "parser"), big);
    EXPECT_TRUE(runIsolated([] { return std::vector<std::uint8_t>(); }, "x", "parser").empty());
    // The child's memory is its own: what it changes stays there.
    int counter = 1;
    runIsolated(
        [&] {
            counter = 2;
            return std::vector<std::uint8_t>{1};
        },
        "x", "parser");
    EXPECT_EQ(counter, 1);
}

TEST(Isolate, ErrorsComeBackWithTheirMessage) {
    EXPECT_EQ(errorOf([]() -> std::vector<std::uint8_t> { throw Error("model 'x': no triangles"); }),
              "model 'x': no triangles");
    EXPECT_EQ(errorOf([]() -> std::vector<std::uint8_t> { throw std::runtime_error("raw"); }), "raw");
}

TEST(Isolate, ADyingChildIsAnError) {
    const std::string aborted = errorOf([]() -> std::vector<std::uint8_t> { std::abort(); });
    EXPECT_NE(aborted.find("model 'x': the parser stopped abnormally"), std::string::npos) << aborted;
    const std::string killed = errorOf([]() -> std::vector<std::uint8_t> {
        std::raise(SIGKILL);
        return {};
    });
    EXPECT_NE(killed.find("signal 9"), std::string::npos) << killed;
    const std::string exited = errorOf([]() -> std::vector<std::uint8_t> { std::_Exit(7); });
    EXPECT_NE(exited.find("exit status 7"), std::string::npos) << exited;
}

TEST(Isolate, WorksWhileThePoolHasThreads) {
    // The parent's oneTBB workers do not exist in the child; work that does not use them runs.
    parallelRows(1024, Exec{}, [](int, int) {});
    EXPECT_EQ(runIsolated([] { return std::vector<std::uint8_t>{42}; }, "x", "parser"), std::vector<std::uint8_t>{42});
}

}  // namespace
}  // namespace ssfx::test

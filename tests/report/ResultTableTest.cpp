// SPDX-License-Identifier: BSD-3-Clause
// A typed result table written once for every format (report/ResultTable.h):
// the same cells as JSON, CSV and Markdown.
#include <limits>
#include <string>

#include <catch2/catch.hpp>

#include "report/ResultTable.h"

using namespace bandlight;

namespace
{
ResultTable Example()
{
    ResultTable t({"method", "mean", "threads", "shipped", "note"});
    t.add({std::string("bradford"), 1.25, 2LL, true, ResultCell()});
    t.add({std::string("a, \"quoted\" | name"), std::numeric_limits<double>::quiet_NaN(), 1LL,
           false, std::string("two\nlines")});
    return t;
}
}  // namespace

TEST_CASE("A result table's JSON keeps types and column order", "[report][table]")
{
    const nlohmann::ordered_json j = Example().json();
    REQUIRE(j.size() == 2);
    CHECK(j[0].dump() ==
          R"({"method":"bradford","mean":1.25,"threads":2,"shipped":true,"note":null})");
    // A non-finite number is null: JSON has no NaN.
    CHECK(j[1]["mean"].is_null());
    CHECK(j[1]["threads"].is_number_integer());
}

TEST_CASE("A result table's CSV quotes what needs quoting, empty for no value", "[report][table]")
{
    CHECK(Example().csv() ==
          "method,mean,threads,shipped,note\n"
          "bradford,1.25,2,true,\n"
          "\"a, \"\"quoted\"\" | name\",,1,false,\"two\nlines\"\n");
}

TEST_CASE("A result table's Markdown escapes bars and line breaks", "[report][table]")
{
    CHECK(Example().markdown() ==
          "| method | mean | threads | shipped | note |\n"
          "|---|---|---|---|---|\n"
          "| bradford | 1.25 | 2 | true |  |\n"
          "| a, \"quoted\" \\| name |  | 1 | false | two lines |\n");
}

TEST_CASE("A row of the wrong width is refused", "[report][table]")
{
    ResultTable t({"a", "b"});
    CHECK_THROWS_AS(t.add({1.0}), std::invalid_argument);
}

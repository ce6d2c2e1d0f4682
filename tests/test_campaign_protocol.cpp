// A campaign's `protocol` (docs/campaigns.md, "Published protocols"): BBOB 2009's runs (instances
// 1-5, 3 trials each, dimensions 2-40, the final target 1e-8, the entrant's budget) and the CEC
// competitions' (one suite, its runs and MaxFES) filled in where the file is silent, and every
// difference refused in one line naming the file and the key.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "experiment/campaign/prepare.hpp"
#include "experiment/campaign/toml.hpp"
#include "framework/error.hpp"
#include "tests/cli_runner.hpp"
#include "tests/test_support.hpp"

namespace {

using pride::test::TempDir;

const std::string algorithm = "[[algorithm]]\nid = \"de\"\ntype = \"de\"\n";

pride::campaign::Campaign prepared(const TempDir& dir, const std::string& body) {
    auto c = pride::campaign::parse_campaign(dir.write("p.toml", "name = \"p\"\n" + body + algorithm));
    pride::campaign::prepare(c);
    return c;
}

std::string refusal(const TempDir& dir, const std::string& body) {
    return pride::test::input_error_message([&] { prepared(dir, body); });
}

}  // namespace

TEST_CASE("protocol bbob-2009: instances 1-5, three trials, the final target 1e-8", "[campaign][protocol]") {
    const TempDir dir;
    const auto c = prepared(dir,
                            "protocol = \"bbob-2009\"\n[budget]\nevaluations_per_dim = 100\n"
                            "[[suite]]\nname = \"bbob\"\nfunctions = [1, 6]\ndimensions = [2, 5]\n");
    CHECK(c.seeds == 3);
    CHECK(c.seed_list.empty());
    REQUIRE(c.target_precision.has_value());
    CHECK(*c.target_precision == 1e-8);
    REQUIRE(c.problems.size() == 2 * 2 * 5);
    for (const auto& p : c.problems) {
        const auto& f = std::get<pride::engine::ContinuousSpec>(p.spec);
        INFO(p.id);
        CHECK(p.evaluations == 100 * f.dim);
        CHECK(*f.instance >= 1);
        CHECK(*f.instance <= 5);
    }
    // seeds = 3 and precision = 1e-8 say the same.
    CHECK(prepared(dir,
                   "protocol = \"bbob-2009\"\nseeds = 3\n[budget]\nevaluations = 500\nprecision = 1e-8\n"
                   "[[suite]]\nname = \"bbob\"\nfunctions = [2]\ndimensions = [3]\n")
              .seeds == 3);
}

TEST_CASE("protocol bbob-2009: what differs from BBOB 2009 is refused by name", "[campaign][protocol]") {
    const TempDir dir;
    const std::string suite = "[[suite]]\nname = \"bbob\"\nfunctions = [1]\ndimensions = [2]\n";
    const std::string budget = "[budget]\nevaluations_per_dim = 100\n";
    const std::string p = "protocol = \"bbob-2009\"\n";
    CHECK(
        refusal(dir, p + budget + "[[suite]]\nname = \"bbob\"\nfunctions = [1]\ndimensions = [2]\ninstances = [1, 2]\n")
            .find("p.toml:2: protocol 'bbob-2009': bbob-f1 in dimension 2 runs instances 1, 2; BBOB 2009 ran "
                  "instances 1-5") != std::string::npos);
    CHECK(refusal(dir, p + budget + "[[suite]]\nname = \"bbob\"\nfunctions = [1]\ndimensions = [4]\n")
              .find("has dimension 4; BBOB 2009 ran 2, 3, 5, 10, 20 and 40") != std::string::npos);
    CHECK(refusal(dir, p + "seeds = 5\n" + budget + suite).find("3 trials per instance") != std::string::npos);
    CHECK(refusal(dir, p + "seeds = [1, 2, 3]\n" + budget + suite).find("give seeds = 3") != std::string::npos);
    CHECK(refusal(dir, p + suite).find("budget was each entrant's own") != std::string::npos);
    CHECK(refusal(dir, p + budget + "target = 1.0\n" + suite).find("give [budget] precision, not target") !=
          std::string::npos);
    CHECK(refusal(dir, p + budget + "precision = 1e-6\n" + suite).find("final target is f_opt + 1e-8") !=
          std::string::npos);
    const std::string other =
        refusal(dir, p + budget + suite + "[[problem]]\nid = \"s\"\ntype = \"sphere\"\ndim = 2\n");
    CHECK(other.find("problem 's' is not of the [[suite]] bbob") != std::string::npos);
    CHECK(other.rfind(dir.file("p.toml") + ":", 0) == 0);
    // An unknown protocol is refused where the file names it, with the names it may take.
    CHECK(pride::test::input_error_message([&] {
              pride::campaign::parse_campaign(dir.write("u.toml", "name = \"u\"\nprotocol = \"bbob-2010\"\n"));
          }) == dir.file("u.toml") + ":2:12: unknown protocol 'bbob-2010' (bbob-2009, cec2017, cec2022, cec2020rw)");
    CHECK(pride::test::input_error_message([&] {
              pride::campaign::parse_campaign(dir.write("u.toml", "name = \"u\"\nprotocol = 2009\n"));
          }).find("'protocol' must be a string") != std::string::npos);
}

TEST_CASE("protocol cec2020rw, cec2017: the suite's runs and MaxFES, nothing else", "[campaign][protocol]") {
    const TempDir dir;
    const std::string suite = "[[suite]]\nname = \"cec2020rw\"\nfunctions = [24, 34]\n";
    const auto c = prepared(dir, "protocol = \"cec2020rw\"\n" + suite);
    CHECK(c.seeds == 25);
    REQUIRE(c.problems.size() == 2);
    CHECK(c.problems[0].evaluations == 100000);  // the guidelines' eq. 1: D = 7
    CHECK(c.problems[1].evaluations == 800000);  // D = 118
    CHECK(refusal(dir, "protocol = \"cec2020rw\"\nseeds = 10\n" + suite)
              .find("the competition made 25 runs per problem (seeds 1-25)") != std::string::npos);
    CHECK(refusal(dir, "protocol = \"cec2020rw\"\n[budget]\nevaluations = 1000\n" + suite)
              .rfind(dir.file("p.toml") + ":4: protocol 'cec2020rw': the competition's MaxFES is the budget", 0) == 0);
    // Refused before any data is read: CEC 2017's problems are not CEC 2022's.
    CHECK(refusal(dir, "protocol = \"cec2022\"\n[[suite]]\nname = \"cec2017\"\nfunctions = [1]\ndimensions = [10]\n")
              .find("protocol 'cec2022': problem 'cec2017-f1-d10' is not of the suite") != std::string::npos);
}

TEST_CASE("protocol: pride bench refuses a campaign that differs, exit 2, no store", "[campaign][protocol]") {
    const TempDir dir;
    const std::string file = dir.write("b.toml",
                                       "name = \"b\"\nprotocol = \"bbob-2009\"\nseeds = 2\n[budget]\n"
                                       "evaluations_per_dim = 10\n[[suite]]\nname = \"bbob\"\n"
                                       "functions = [1]\ndimensions = [2]\n" +
                                           algorithm);
    pride::test::check_input_error(pride::test::run_pride("bench '" + file + "' --out '" + dir.file("b.sqlite") + "'"),
                                   {"b.toml:2: protocol 'bbob-2009'", "3 trials per instance"});
    CHECK(!std::filesystem::exists(dir.file("b.sqlite")));
}

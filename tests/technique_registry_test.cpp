// The technique registry: every entry found by its name, owning its override
// keys; techniques with overrides parsed and validated; bad ones refused with the
// technique named.
#include <catch2/catch.hpp>

#include <algorithm>
#include <set>
#include <string>

#include "core/error.h"
#include "pipeline/pcss_settings.h"
#include "technique/technique_registry.h"

TEST_CASE("technique registry: every entry parses by its own name, names are unique") {
  std::set<std::string> names;
  for (const pn::TechniqueEntry& e : pn::technique_registry()) {
    const auto config = pn::parse_technique(e.name);
    CHECK(config->name() == e.name);
    CHECK(!config->keys().empty());
    CHECK(names.insert(e.name).second);
  }
  for (const std::string& technique : pn::render_techniques()) CHECK(names.count(technique) == 1);
  for (const std::string& technique : pn::bench_techniques()) CHECK(names.count(technique) == 1);
  CHECK(names.count(pn::kExactTechnique) == 1);
  CHECK(names.count(pn::kPoissonTechnique) == 1);
}

TEST_CASE("technique registry: the default lists come from the entries (issue 41: a new entry runs everywhere)") {
  // What render, bench pipeline and the frontier ran before the lists were derived: the entries say
  // the same (the registry's order is render's sheet's).
  CHECK(pn::render_techniques() ==
        std::vector<std::string>{"exact", "poisson", "hqepcss", "fast-paper", "fast", "savsm", "backprojection"});
  const std::vector<std::string> frontier = pn::frontier_techniques();
  CHECK(frontier.size() == 31);  // the same 31 points as before, in the registry's order
  for (const std::string& t : frontier) CHECK(pn::parse_technique(t)->name() == t);  // every variant parses
  CHECK(std::count(frontier.begin(), frontier.end(), "vogel:receiver-plane=1") == 1);
  CHECK(std::count(frontier.begin(), frontier.end(), "fast-paper") == 0);
  // An entry left at the defaults is in every list; an ablation opts out and names its family.
  const pn::TechniqueEntry fresh{.name = "x", .summary = "", .make = nullptr};
  CHECK(fresh.rendered);
  CHECK(fresh.benched);
  CHECK(fresh.frontier == std::vector<const char*>{""});
  CHECK(pn::technique_family("fast-leaf-8") == "fast");
  CHECK(pn::technique_family("evsm2:exponent=20") == "vsm");
  CHECK(pn::technique_family("backprojection:samples=16") == "backprojection");
  CHECK_THROWS_WITH(pn::technique_family("slow"), Catch::StartsWith("unknown technique 'slow'"));
}

TEST_CASE("technique registry: a technique with overrides keeps its full name and its entry's keys") {
  const auto config = pn::parse_technique("fast:leaf=4:reuse=off:region=centred:c=1.5");
  CHECK(config->name() == "fast:leaf=4:reuse=off:region=centred:c=1.5");
  CHECK(config->keys() == pn::pcss_setting_keys());
  const auto copy = config->clone();
  CHECK(copy->name() == config->name());
}

TEST_CASE("technique registry: bad techniques are refused naming the technique (negative)") {
  CHECK_THROWS_WITH(pn::parse_technique("slow"), Catch::StartsWith("unknown technique 'slow': expected one of exact, poisson, hqepcss, fast-paper, fast, fast-no-refine"));
  CHECK_THROWS_WITH(pn::parse_technique("fast:leaf"), "technique 'fast:leaf': 'leaf': expected key=value");
  CHECK_THROWS_WITH(pn::parse_technique("fast:colour=red"), Catch::StartsWith("technique 'fast:colour=red': unknown setting 'colour'"));
  CHECK_THROWS_WITH(pn::parse_technique("fast:bias=-1"), "technique 'fast:bias=-1': bias -1: expected a finite number >= 0");
  CHECK_THROWS_WITH(pn::parse_technique("fast:search-tile=17"), "technique 'fast:search-tile=17': search reuse tile 17: expected 0 (off) or 1..16");
}

TEST_CASE("technique registry: vsm and evsm take their own keys and refuse values out of range (negative)") {
  const auto config = pn::parse_technique("vsm:radius=5:sigma=1.5:bleeding=0.3:min-variance=1e-5:bias=0.05");
  CHECK(config->name() == "vsm:radius=5:sigma=1.5:bleeding=0.3:min-variance=1e-5:bias=0.05");
  CHECK(pn::parse_technique("evsm:exponent=30:negative-exponent=10")->name() == "evsm:exponent=30:negative-exponent=10");
  CHECK(pn::parse_technique("evsm2:exponent=20")->name() == "evsm2:exponent=20");
  CHECK_THROWS_WITH(pn::parse_technique("vsm:bleeding=1"),
                    "technique 'vsm:bleeding=1': vsm bleeding reduction 1: expected 0 to 0.99");
  CHECK_THROWS_WITH(pn::parse_technique("evsm:exponent=50"),
                    Catch::StartsWith("technique 'evsm:exponent=50': evsm exponent 50: expected 0 to 42"));
  CHECK_THROWS_WITH(pn::parse_technique("vsm:radius=17"),
                    "technique 'vsm:radius=17': blur radius 17: expected an integer from 0 to 16");
  CHECK_THROWS_WITH(pn::parse_technique("vsm:radius=x"), "technique 'vsm:radius=x': radius=x: expected an integer");
  CHECK_THROWS_WITH(pn::parse_technique("vsm:colour=red"),
                    Catch::StartsWith("technique 'vsm:colour=red': unknown setting 'colour': expected radius, sigma"));
}

TEST_CASE("technique registry: savsm and its ablations take their own keys and refuse bad values (negative)") {
  for (const char* name : {"savsm", "savsm-table", "savsm-float", "savsm-raw"}) CHECK(pn::parse_technique(name)->name() == name);
  const char* technique = "savsm:bias=0.05:scale=2:min-variance=1e-5:bleeding=0.3:blocker=table:bound=off:table=float";
  CHECK(pn::parse_technique(technique)->name() == technique);
  CHECK_THROWS_WITH(pn::parse_technique("savsm:table=half"), "technique 'savsm:table=half': table=half: expected fixed or float");
  CHECK_THROWS_WITH(pn::parse_technique("savsm:blocker=mean"),
                    "technique 'savsm:blocker=mean': blocker=mean: expected table or min");
  CHECK_THROWS_WITH(pn::parse_technique("savsm:bound=1"), "technique 'savsm:bound=1': bound=1: expected on or off");
  CHECK_THROWS_WITH(pn::parse_technique("savsm:bleeding=1"),
                    Catch::StartsWith("technique 'savsm:bleeding=1': savsm bleeding reduction 1: expected"));
  CHECK_THROWS_WITH(pn::parse_technique("savsm:scale=-1"),
                    "technique 'savsm:scale=-1': savsm filter scale -1: expected 0..64 (the filter side in penumbrae)");
  CHECK_THROWS_WITH(pn::parse_technique("savsm:radius=3"),
                    Catch::StartsWith("technique 'savsm:radius=3': unknown setting 'radius': expected bias, scale"));
}

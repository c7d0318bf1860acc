// The typed records of design.json (design/verdict.hpp, design/comparison.hpp): what design writes reads back the
// same, and a damaged document is refused naming the place.
#include <gtest/gtest.h>

#include <stdexcept>

#include "design/comparison.hpp"
#include "design/estimates.hpp"
#include "design/members_json.hpp"
#include "design/verdict.hpp"

namespace dmi::design {
namespace {

Check check(const std::string& id, const std::string& level, const std::string& situation, double demand, double capacity) {
  Check c;
  c.id = id, c.title = id, c.member = "dam", c.material = "concrete", c.unit = "Pa", c.level = level, c.situation = situation;
  c.demand = demand, c.capacity = capacity, c.s_m = 0.5, c.position = 0.1, c.time_s = 0.02, c.x_m = 1, c.y_m = 2;
  c.formula = "sigma <= f", c.source = "a clause";
  c.finish();
  return c;
}

TEST(DesignRecords, VerdictByHandAndBackFromItsJson) {
  const std::vector<Check> checks = {check("a", "serviceability", "accidental", 0.5, 1), check("b", "ultimate", "accidental", 1.2, 1),
                                     check("c", "serviceability", "persistent", 0.9, 1), check("d", "information", "accidental", 3, 1)};
  const Verdict v = run_verdict(checks, "both");
  EXPECT_EQ(v.checks, 3);  // the information check is never judged
  EXPECT_EQ(v.failed, 1);
  EXPECT_FALSE(v.passed);
  EXPECT_EQ(v.governing->id, "b");
  EXPECT_EQ(v.levels.at("serviceability").governing->id, "c");
  EXPECT_TRUE(v.levels.at("serviceability").passed);
  EXPECT_EQ(v.situations.at("persistent").checks, 1);
  EXPECT_EQ(v.levels.at("information").checks, 1);
  const Verdict only = run_verdict(checks, "serviceability");
  EXPECT_TRUE(only.passed);
  EXPECT_DOUBLE_EQ(only.max_utilisation(), 0.9);
  const nlohmann::json j = to_json(v);
  EXPECT_EQ(to_json(verdict_from_json(j, false, "test")), j);
  const Check back = check_from_json(j["governing"], "test");
  EXPECT_EQ(back.to_json(), checks[1].to_json());
}

TEST(DesignRecords, DamagedVerdictIsRefusedNamingThePlace) {
  nlohmann::json j = to_json(run_verdict({check("a", "ultimate", "accidental", 0.5, 1)}, "both"));
  j["levels"]["ultimate"]["governing"]["demand"] = "high";
  try {
    verdict_from_json(j, false, "design.json runs[0].verdict");
    FAIL() << "accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("runs[0].verdict.levels.ultimate.governing.demand"), std::string::npos) << e.what();
  }
}

TEST(DesignRecords, ComparisonsReadBackTheSame) {
  BufferComparison c;
  c.quantities = {{"base_shear", "peak base shear", "N", 4.5e5, 9.0e6, 95.0}, {"x", "a zero bare value", "N", 1, 0, std::nullopt}};
  c.note = "n";
  EXPECT_EQ(to_json(*comparison_from_json(to_json(c), "test")), to_json(c));
  PlaneAndSpace p;
  p.pairs = {{"with_buffer", true, false, {{"base_shear", "peak base shear", "N", 2, 1, 2.0}}}};
  p.note = "ratio";
  EXPECT_EQ(to_json(*plane_and_space_from_json(to_json(p), "test")), to_json(p));
  EXPECT_FALSE(comparison_from_json(nullptr, "test").has_value());
  EXPECT_THROW(comparison_from_json(nlohmann::json{{"note", "n"}}, "test"), std::runtime_error);
}

TEST(DesignRecords, MemberEnvelopeReadsBackTheSame) {
  for (int dim : {2, 3}) {
    MemberEnvelope m;
    m.dim = dim, m.name = "dam", m.cls = "concrete", m.length = 4;
    for (int k = 0; k < 3; ++k) {
      Station st;
      st.position = 0.5 * k, st.s_m = 2.0 * k, st.x = 0.1, st.y = 2.0 * k, st.z = dim == 3 ? 0.3 : 0.0, st.depth = 1.2;
      st.N_max.max(1e3 * k, 0.01), st.sigma_tension.max(1e6 * (3 - k), 0.02), st.sigma_compression.min(-2e6, 0.03);
      if (dim == 3) st.T_abs.max(50, 0.04), st.principal.max(1.5e6, 0.05);
      m.stations.push_back(st);
    }
    nlohmann::json run = {{"dimension", dim}, {"members", {member_json(m)}}};
    const std::vector<MemberEnvelope> back = members_from_json(run, "test");
    ASSERT_EQ(back.size(), 1u);
    EXPECT_EQ(member_json(back[0]), member_json(m));
    EXPECT_FALSE(back[0].stations[0].M_max.set);  // unset stays unset
    run["members"][0]["stations"][1]["sigma_tension_max_Pa"] = 3;
    EXPECT_THROW(members_from_json(run, "test"), std::runtime_error);
  }
}

TEST(DesignRecords, EstimatesReadBackTheSame) {
  Estimate a{"sdof", "SDOF", "F = k x", "a paper", "k 1", true, 2e6, "peak_base_shear", 1e6, 2.0, ""};
  Estimate b{"hertz", "Hertz", "F = ...", "Hertz 1882", "", false, 0, "peak_contact_force", 0, 0, "a sphere on a half-space"};
  Estimate c = a;
  c.grid = true, c.simulated_gci = 0.1, c.ratio_low = 2.0 / 1.1, c.ratio_high = 2.0 / 0.9;  // extrapolated: not converged
  for (const Estimate& e : {a, b, c}) EXPECT_EQ(estimate_from_json(e.to_json(), "test").to_json(), e.to_json());
  nlohmann::json bad = a.to_json();
  bad["value_N"] = nullptr;  // an applicable estimate without a value
  EXPECT_THROW(estimate_from_json(bad, "test"), std::runtime_error);
}

}  // namespace
}  // namespace dmi::design

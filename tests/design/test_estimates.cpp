// The design-practice load table (design/estimates.cpp): which models apply to which scenario, the values against
// hand calculations, the reasons given where a model does not apply, and the grid uncertainty attached to each ratio.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "design/estimates.hpp"
#include "design/grid_study.hpp"
#include "design/grid_study_record.hpp"
#include "engine/scenario/design_basis_json.hpp"

namespace dmi::design {
namespace {

using nlohmann::json;

json basis(bool buffer) {
  json b = json::parse(R"({
    "dam": {"type": "concrete_gravity", "height_m": 4, "width_m": 2, "crest_thickness_m": 1, "base_thickness_m": 1.6,
            "youngs_modulus_Pa": 25e9, "poisson_ratio": 0.2, "density_kg_m3": 2400},
    "boulder": {"mass_kg": 1000, "diameter_m": 0.894, "density_kg_m3": 2650, "youngs_modulus_Pa": 50e9,
                "poisson_ratio": 0.25, "speed_m_s": 5, "impact_height_m": 3.6, "model": "rigid"}})");
  if (buffer) b["tyre_buffer"] = json{{"type", "homogenised"}, {"youngs_modulus_Pa", 2e6}, {"poisson_ratio", 0.3}, {"thickness_m", 0.3}};
  return b;
}

// The estimates of a design basis as results.h5 carries it (read and validated as design/ reads it).
std::vector<Estimate> est(const json& b, double shear, double contact) {
  return estimates(design_basis_from_json(b, "r.h5", "/documents/design_basis"), shear, contact);
}

const Estimate& row(const std::vector<Estimate>& t, const std::string& id) {
  for (const auto& e : t)
    if (e.id == id) return e;
  throw std::runtime_error("no row " + id);
}

// Bare face, m = 1 t at 5 m/s, concrete E = 25 GPa, nu = 0.2:
//   lambda = 25e9 * 0.2 / (1.2 * 0.6) = 6.9444e9 Pa; H = 25 / 19.62 = 1.27421 m; W = 9.81 kN;
//   P = 2.108 * 9.81^(2/3) * 6.9444e6^0.4 * 1.27421^0.6 = 2.108 * 4.5826076 * 545.32449 * 1.1564972 = 6092.3225 kN.
TEST(DesignEstimates, BareFaceRowsAndJapaneseHandValue) {
  const auto t = est(basis(false), 2.0e5, 4.0e6);
  for (const char* id : {"sdof_base_force", "en1991_hard_impact", "hertz", "geo_hertz", "japanese_rockfall"}) EXPECT_TRUE(row(t, id).applicable) << id;
  EXPECT_FALSE(row(t, "astra_gallery").applicable);
  EXPECT_EQ(row(t, "astra_gallery").note, "needs a cushion layer");
  const Estimate& jp = row(t, "japanese_rockfall");
  EXPECT_NEAR(jp.value, 6092322.5, 1.0);
  EXPECT_NEAR(jp.ratio, jp.value / 4.0e6, 1e-12);
  EXPECT_NE(jp.parameters.find("H = 1.27 m"), std::string::npos) << jp.parameters;
  EXPECT_NEAR(row(t, "sdof_base_force").ratio, row(t, "sdof_base_force").value / 2.0e5, 1e-12);  // against the base shear
}

// Buffer E = 2 MPa, nu = 0.3, t = 0.3 m; r = 0.447 m; E_k = 12.5 kJ:
//   lambda = 2e6 * 0.3 / (1.3 * 0.4) = 1.1538e6 Pa -> P = 2.108 * 4.5826076 * 16.782597 * 1.1564972 = 187.49386 kN;
//   M_E = 2e6 * 0.7 / (1.3 * 0.4) = 2.6923e6 Pa; phi = 30 deg assumed:
//   F = 2.8 * 0.3^-0.5 * 0.447^0.7 * 2692.3^0.4 * tan 30 * 12.5^0.6
//     = 2.8 * 1.8257419 * 0.56913496 * 23.553198 * 0.57735027 * 4.5514105 = 180.07272 kN.
TEST(DesignEstimates, BufferedRowsHandValues) {
  const auto t = est(basis(true), 1.0e5, 2.0e5);
  EXPECT_FALSE(row(t, "hertz").applicable);
  EXPECT_FALSE(row(t, "geo_hertz").applicable);
  EXPECT_NEAR(row(t, "japanese_rockfall").value, 187493.86, 0.05);
  const Estimate& as = row(t, "astra_gallery");
  EXPECT_NEAR(as.value, 180072.72, 0.05);
  EXPECT_NE(as.note.find("30° assumed"), std::string::npos) << as.note;
  json b = basis(true);
  b["tyre_buffer"]["friction_angle_deg"] = 40.0;  // a given angle is used and the note drops the assumption
  const auto t40 = est(b, 1.0e5, 2.0e5);
  const Estimate& as40 = row(t40, "astra_gallery");
  EXPECT_NEAR(as40.value / as.value, std::tan(40 * M_PI / 180) / std::tan(30 * M_PI / 180), 1e-12);
  EXPECT_EQ(as40.note.find("assumed"), std::string::npos);
  // A results file written before the buffer's Poisson ratio was recorded: the two cushion rows say why they are empty.
  b.erase("tyre_buffer"), b["tyre_buffer"] = json{{"youngs_modulus_Pa", 2e6}, {"thickness_m", 0.3}};
  const auto old = est(b, 1.0e5, 2.0e5);
  EXPECT_FALSE(row(old, "japanese_rockfall").applicable);
  EXPECT_NE(row(old, "astra_gallery").note.find("poisson_ratio"), std::string::npos);
  EXPECT_TRUE(row(old, "astra_gallery").to_json()["value_N"].is_null());
}

// Debris, rho = 2000, v = 6, h = 1, w = 2: GEO 360 kN, hydrostatic + dynamic 163.62 kN, momentum flux 144 kN.
TEST(DesignEstimates, DebrisRowsHandValues) {
  json b = basis(false);
  b.erase("boulder");
  b["debris_surge"] = json{{"density_kg_m3", 2000}, {"depth_m", 1}, {"speed_m_s", 6}};
  const auto t = est(b, 0, 3.0e5);
  ASSERT_EQ(t.size(), 4u);
  EXPECT_NEAR(row(t, "geo_debris").value, 360000.0, 1e-6);
  EXPECT_NEAR(row(t, "hydrostatic_dynamic").value, 163620.0, 1e-6);
  EXPECT_NEAR(row(t, "surge_momentum_flux").value, 144000.0, 1e-6);
  EXPECT_NEAR(row(t, "geo_debris").ratio, 1.2, 1e-12);
  EXPECT_FALSE(row(t, "blunt_front_wave").applicable);  // results written before the modulus was recorded
  // With E 20 MPa, nu 0.3: rho c v h w = 2000 * 116.024 * 6 * 1 * 2 = 2 784.6 kN; the note names the snout.
  b["debris_surge"].update(json{{"youngs_modulus_Pa", 20e6}, {"poisson_ratio", 0.3}, {"front_length_m", 2.47}});
  const auto w = est(b, 0, 3.0e5);
  EXPECT_NEAR(row(w, "blunt_front_wave").value, 2784572.9, 0.1);
  EXPECT_NE(row(w, "blunt_front_wave").note.find("snout is 2.47 m long"), std::string::npos) << row(w, "blunt_front_wave").note;
  EXPECT_EQ(row(w, "blunt_front_wave").note.find("above the 20 MPa"), std::string::npos);
  b["debris_surge"]["youngs_modulus_Pa"] = 80e6;  // beyond the range shown: the note says so
  EXPECT_NE(row(est(b, 0, 3.0e5), "blunt_front_wave").note.find("E = 80 MPa is above the 20 MPa"), std::string::npos);
  b["debris_surge"]["youngs_modulus_Pa"] = 20e6;
  b["debris_surge"]["front_length_m"] = 0;
  EXPECT_NE(row(est(b, 0, 3.0e5), "blunt_front_wave").note.find("blunt front"), std::string::npos);
  // A slurry: K = 7.2 MPa, c0 = 60 m/s: rho c0 v h w = 2000 * 60 * 6 * 1 * 2 = 1 440 kN.
  json sl = b;
  sl["debris_surge"].erase("youngs_modulus_Pa"), sl["debris_surge"].erase("poisson_ratio");
  sl["debris_surge"]["bulk_modulus_Pa"] = 7.2e6, sl["debris_surge"]["front_length_m"] = 1.0;
  const auto ts = est(sl, 0, 3.0e5);
  EXPECT_NEAR(row(ts, "blunt_front_wave").value, 1440000.0, 1e-6);
  EXPECT_NE(row(ts, "blunt_front_wave").note.find("c₀ = 60 m/s"), std::string::npos) << row(ts, "blunt_front_wave").note;
  b["debris_surge"]["front_length_m"] = "long";
  EXPECT_THROW(est(b, 0, 3.0e5), std::runtime_error);
}

TEST(DesignEstimates, MissingBasisNumberNamesTheKey) {
  json b = basis(false);
  b["boulder"].erase("speed_m_s");
  try {
    est(b, 1, 1);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("r.h5: /documents/design_basis/boulder/speed_m_s: expected a number > 0 (missing)"), std::string::npos)
        << e.what();
  }
  // Numbers that go together: water's height without its unit weight names the missing one.
  json w = basis(false);
  w["dam"]["water_height_m"] = 3.0;
  try {
    est(w, 1, 1);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("r.h5: /documents/design_basis/dam/water_unit_weight_N_m3: expected a number (missing; it goes with"),
              std::string::npos) << e.what();
  }
}

// A grid study of 10 % on the contact force puts the ratio of 2.0 between 2.0 / 1.1 and 2.0 / 0.9.
TEST(DesignEstimates, GridUncertaintyBandsTheRatio) {
  DesignDocument design;
  RunDesign run;
  run.estimates = est(basis(false), 2.0e5, 4.0e6);
  design.runs = {run};
  GridStudyRecord gs;  // the study as design writes it, of the contact force alone
  GridQuantity q;
  q.variant = "", q.id = "contact_force", q.gci = 0.1, q.extrapolated = 4.2e6, q.values = {4.0e6, 3.9e6, 3.7e6};
  gs.quantities = {q};
  design.grid_study = gs;
  add_grid_uncertainty(design);
  for (const Estimate& est : design.runs[0].estimates) {
    const json e = est.to_json();
    if (e["compare_to"] == "peak_contact_force" && e["applicable"].get<bool>()) {
      const double r = e["ratio"];
      EXPECT_NEAR(e["ratio_low"].get<double>(), r / 1.1, 1e-12) << e["id"];
      EXPECT_NEAR(e["ratio_high"].get<double>(), r / 0.9, 1e-12) << e["id"];
      EXPECT_EQ(e["simulated_gci"], 0.1);
    } else {
      EXPECT_FALSE(e.contains("ratio_low")) << e["id"];  // the base shear was not in the study; n/a rows have no ratio
    }
  }
}

}  // namespace
}  // namespace dmi::design

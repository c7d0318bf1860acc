// The solid-FE check of a concrete dam body (Lin, Cheng & Tuan, Table 1): the tapered dam as hex8 (3D) or
// quad4 (2D plane strain) elements, base fixed, linear elastic, one static solve per load case:
//   point      a horizontal force at the upstream-face node nearest to (across, height);
//   patch      the same force spread over a rectangle of the face (pyramid or uniform, Lin, Cheng & Tuan);
//   simulation the horizontal contact loads this run's boulder/debris put on a dam member at the instant
//              of the largest total contact force, binned by height (bins of one MPM cell) into a
//              piecewise-linear face pressure with the same resultant; across the width uniform (the
//              plane-strain assumption) or axisymmetric about the profile's centroid (a round patch).
// Results (JSON document "solid_check" in results.h5, docs/results.md): per case the load resultant,
// peak von Mises / max and min principal stress at Gauss points and at nodes (value and location),
// the largest nodal base reaction, the total base reaction and the largest displacement.
#pragma once
#include <string>

#include "core/peak_contact.hpp"
#include "core/solid_check_record.hpp"
#include "core/solid_field.hpp"
#include "engine/scenario/config.hpp"

namespace dmi {

struct SolidCheckDocuments {
  SolidCheckRecord check;  // the model and the peaks per case (core/solid_check_record.hpp; the design checks read this)
  SolidFieldRecord field;  // the mesh and per case the nodal fields (core/solid_field.hpp; the pictures read this)
};

// peak_contact: the run's contact loads at their peak (null when the members were never touched). Throws InputError
// when a simulation load case has no contact loads to take.
SolidCheckDocuments run_solid_check(const Scenario& s, const PeakContact* peak_contact);
// Builds and factorises the dam body's model now (kept for run_solid_check, which otherwise does it on first use): a
// caller with a core to spare runs it beside the simulations. Errors are left to run_solid_check.
void prepare_solid_check(const SolidCheckConfig& c);

}  // namespace dmi

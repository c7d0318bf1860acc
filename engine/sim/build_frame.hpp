// Turns a scenario's "structure" section into a FrameModel (members subdivided into elements,
// sections, supports, nodal masses) and its "member_contact" section into the coupling options.
#pragma once
#include <string>

#include "core/structure_record.hpp"
#include "engine/mpm/scene.hpp"
#include "engine/scenario/config.hpp"
#include "engine/structure/frame.hpp"

namespace dmi {

FrameModel build_frame_model(const Scenario& s);
SpaceFrameModel build_space_frame_model(const Scenario& s);  // a 3D analysis's structure
// The members as built (core/structure_record.hpp): nodes, elements with sections and materials (a space frame's with
// their depth axis e2), members, supports and the series of their reactions. F: Frame or SpaceFrame.
template <class F> StructureRecord structure_record(const Scenario& s, const F& frame);
// Fields the members act on: those of the listed bodies (all bodies if none are listed).
template <int D> MemberCoupling build_coupling(const Scenario& s, const Scene<D>& scene);

}  // namespace dmi

// The scenario reader's frame and member-contact sections (parse_structure.cpp), for parse.cpp.
#pragma once
#include "engine/scenario/config.hpp"
#include "engine/scenario/schema.hpp"

namespace dmi {

void read_structure(schema::Obj o, StructureConfig& st);
// structure: whether the scenario has members (the section's keys are declared either way).
void read_member_contact(schema::Obj o, MemberContactConfig& c, bool structure);

}  // namespace dmi

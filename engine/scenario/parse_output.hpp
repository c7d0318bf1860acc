// The scenario reader's output and solid_check sections (parse_output.cpp), for parse.cpp.
#pragma once
#include "engine/scenario/config.hpp"
#include "engine/scenario/schema.hpp"

namespace dmi {

void read_output(schema::Obj o, OutputConfig& out);
void read_solid_check(schema::Obj o, SolidCheckConfig& c);

}  // namespace dmi

// The struck face's pressure profile as the run defines it: the chain of members it runs along, the load direction,
// the face's width and its bins (one per element; position along the chain and height above the foot). The histories
// face/pressure, face/resultant and face/height hold its values (docs/results.md, "Pressures").
#pragma once
#include <string>
#include <vector>

namespace dmi {

struct FaceBin {
  std::string member;
  int element = 0;
  double from = 0, to = 0;                 // m along the chain of members
  double height_from = 0, height_to = 0;   // m above the foot, across the load direction
};

struct FaceProfileRecord {
  std::vector<std::string> members;
  std::vector<double> direction;  // unit load direction
  double width = 0;               // m: the face width the pressures are taken over
  std::vector<FaceBin> bins;
};

}  // namespace dmi

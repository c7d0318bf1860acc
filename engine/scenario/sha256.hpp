// SHA-256 (FIPS 180-4) of a byte string, as 64 lowercase hex digits: the input file's fingerprint in reports.
#pragma once
#include <string>

namespace dmi {
std::string sha256_hex(const std::string& bytes);
}

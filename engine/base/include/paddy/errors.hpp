// Error types. Every message names the cause: the parameter and its allowed range, the file and
// line, the available choices. The command line turns them into non-zero exit codes.
#pragma once

#include <stdexcept>
#include <string>

namespace paddy {

// Bad user input (parameter out of range, unknown name, unreadable file...). Exit code 2.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The simulation became unphysical while running (time step too large, NaN). Exit code 3.
struct InstabilityError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Checks lo <= value <= hi and throws InputError "name = value is outside the allowed range
// [lo, hi] unit" otherwise (also for NaN).
void checkRange(const std::string& name, double value, double lo, double hi,
                const std::string& unit = "");

}  // namespace paddy

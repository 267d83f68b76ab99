// Error type of the paddy::doe library.
// Every invalid input (malformed CSV cell, unknown column, rank-deficient design, model with more
// terms than runs ...) is reported by throwing DoeError with a message meant for the user; the
// library never returns a silently wrong table.
#pragma once
#include <stdexcept>
#include <string>

namespace paddy::doe {

class DoeError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

}  // namespace paddy::doe

// Storage for self-registered Lua bindings (function-local statics: safe at static-init time).
#include "registry.hpp"

namespace paddy::lua {

std::vector<Binding>& moduleFunctions() {
  static std::vector<Binding> functions;
  return functions;
}

std::vector<Binding>& simulationMethods() {
  static std::vector<Binding> methods;
  return methods;
}

}  // namespace paddy::lua

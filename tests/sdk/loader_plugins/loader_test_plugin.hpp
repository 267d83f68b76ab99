// Shared by the loader's test plugins: a normal sub-model entry with a given name and description
// (its factory is never called; the loader tests only look at what is registered).
#pragma once
#include <paddy/plugin.hpp>

#include <memory>
#include <string>

namespace loader_test {

inline paddy::SubModelInfo normalModel(const std::string& name, const std::string& description) {
  paddy::SubModelInfo info;
  info.name = name;
  info.kind = paddy::SubModelKind::Normal;
  info.description = description;
  info.create = [](const paddy::ParamValues&, const paddy::MaterialPair&) -> std::unique_ptr<paddy::SubModel> {
    return nullptr;
  };
  return info;
}

}  // namespace loader_test

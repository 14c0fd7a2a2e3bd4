// The JSON parses of the test support (golden.hpp), instantiated here once for every test file.
#include "support/golden.hpp"

namespace pgamesh::test {

json parse_json(const std::string& text) {
  return json::parse(text);
}

json load_golden(const std::string& name) {
  std::ifstream in(std::string(PGAMESH_GOLDEN_DIR) + "/" + name);
  if (!in) throw std::runtime_error("cannot open golden file " + name);
  return json::parse(in);
}

}  // namespace pgamesh::test

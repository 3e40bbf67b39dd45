#include "scenario/yaml_internal.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace rearm::scenario::detail {

YAML::Node single_document(const std::string& text, const std::string& source, const char* kind,
                           const char* required) {
  std::vector<YAML::Node> docs;
  try {
    docs = YAML::LoadAll(text);
  } catch (const YAML::Exception& e) {
    if (e.mark.is_null()) throw ScenarioError(source, kDocumentKey, "malformed YAML: " + e.msg);
    throw ScenarioError(
        source,
        "line " + std::to_string(e.mark.line + 1) + ", column " + std::to_string(e.mark.column + 1),
        "malformed YAML: " + e.msg);
  }
  if (docs.empty()) {
    throw ScenarioError(
        source, kDocumentKey,
        std::string("the document is empty (a ") + kind + " needs at least " + required + ")");
  }
  if (docs.size() > 1) {
    throw ScenarioError(source, kDocumentKey,
                        std::string("more than one YAML document (one ") + kind +
                            " per file; the second starts at line " +
                            std::to_string(docs[1].Mark().line + 1) + ")");
  }
  return docs.front();
}

std::string read_text_file(const std::string& path, const char* what) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw ScenarioError(path, "file", std::string("cannot read ") + what + ": it is a directory");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw ScenarioError(path, "file",
                        std::string("cannot read ") + what + ": " + std::strerror(errno));
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) {
    throw ScenarioError(path, "file",
                        std::string("cannot read ") + what + ": " + std::strerror(errno));
  }
  return text.str();
}

}  // namespace rearm::scenario::detail

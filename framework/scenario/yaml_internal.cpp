#include "scenario/yaml_internal.h"

#include <yaml-cpp/eventhandler.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace rearm::scenario::detail {

namespace {

// Records where each document starts and nothing else (no node is built).
class DocumentStarts : public YAML::EventHandler {
 public:
  std::vector<YAML::Mark> starts;
  void OnDocumentStart(const YAML::Mark& mark) override { starts.push_back(mark); }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
};

std::string at(const YAML::Mark& mark) {
  return "line " + std::to_string(mark.line + 1) + ", column " + std::to_string(mark.column + 1);
}

[[noreturn]] void malformed(const std::string& source, const YAML::Exception& e) {
  if (e.mark.is_null()) throw ScenarioError(source, kDocumentKey, "malformed YAML: " + e.msg);
  throw ScenarioError(source, at(e.mark), "malformed YAML: " + e.msg);
}

// The start of every document, up to the third. yaml-cpp 0.7 reads a stray ',' or ']' at the
// start of a line after a block mapping as an endless run of empty documents that all start at
// the same place (YAML::LoadAll never returns): a document that does not advance is malformed.
std::vector<YAML::Mark> document_starts(const std::string& text, const std::string& source) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  DocumentStarts seen;
  constexpr std::size_t kEnough = 3;  // one document, a second one, or one that does not advance
  try {
    while (seen.starts.size() < kEnough && parser.HandleNextDocument(seen)) {
      const auto& s = seen.starts;
      if (s.size() >= 2 && s[s.size() - 1].pos == s[s.size() - 2].pos) {
        const YAML::Mark& m = s.back();
        const std::size_t pos = static_cast<std::size_t>(std::max(m.pos, 0));
        const std::string found = pos < text.size() ? std::string(1, text[pos]) : "end of input";
        throw ScenarioError(source, at(m), "malformed YAML: unexpected '" + found + "'");
      }
    }
  } catch (const YAML::Exception& e) {
    malformed(source, e);
  }
  return seen.starts;
}

}  // namespace

YAML::Node single_document(const std::string& text, const std::string& source, const char* kind,
                           const char* required) {
  const std::vector<YAML::Mark> starts = document_starts(text, source);
  if (starts.empty()) {
    throw ScenarioError(
        source, kDocumentKey,
        std::string("the document is empty (a ") + kind + " needs at least " + required + ")");
  }
  if (starts.size() > 1) {
    throw ScenarioError(source, kDocumentKey,
                        std::string("more than one YAML document (one ") + kind +
                            " per file; the second starts at line " +
                            std::to_string(starts[1].line + 1) + ")");
  }
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    malformed(source, e);
  }
}

namespace {

// A folder of more entries is read this far only, for similar_file.
constexpr std::size_t kMaxListedFiles = 10000;

// "; did you mean '…'?" naming a file of the same folder whose name is close to the missing
// one's, or "".
std::string similar_file(const std::string& path) {
  const std::filesystem::path p(path);
  const std::filesystem::path folder = p.has_parent_path() ? p.parent_path() : ".";
  std::error_code ec;
  std::vector<std::string> names;
  for (auto it = std::filesystem::directory_iterator(folder, ec);
       !ec && it != std::filesystem::directory_iterator() && names.size() < kMaxListedFiles;
       it.increment(ec)) {
    names.push_back(it->path().filename().string());
  }
  const std::optional<std::string> near = closest_name(p.filename().string(), names);
  if (!near) return "";
  return "; did you mean '" + (p.has_parent_path() ? (folder / *near).string() : *near) + "'?";
}

}  // namespace

std::string read_text_file(const std::string& path, const char* what) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw ScenarioError(path, "file", std::string("cannot read ") + what + ": it is a directory");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int error = errno;
    throw ScenarioError(path, "file",
                        std::string("cannot read ") + what + ": " + std::strerror(error) +
                            (error == ENOENT ? similar_file(path) : ""));
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

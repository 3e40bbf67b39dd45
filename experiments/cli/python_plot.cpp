#include "python_plot.h"

#include <cstdlib>

namespace rearm::cli {

namespace fs = std::filesystem;

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) {
    if (c == '\'') {
      q += "'\\''";
    } else {
      q += c;
    }
  }
  return q + "'";
}

std::string find_python(const std::vector<std::string>& modules) {
  std::vector<std::string> candidates;
  if (const char* env = std::getenv("REARM_PYTHON"); env && *env) candidates.push_back(env);
  candidates.push_back("python3");
  candidates.push_back("/usr/bin/python3");
  std::string imports;
  for (const std::string& m : modules) imports += "import " + m + "; ";
  for (const std::string& py : candidates) {
    const std::string cmd = shell_quote(py) + " -c " + shell_quote(imports) + " > /dev/null 2>&1";
    if (std::system(cmd.c_str()) == 0) return py;
  }
  return "";
}

fs::path plot_script(const std::string& name) {
  const fs::path here = fs::path(__FILE__).parent_path().parent_path() / "plot" / name;
  if (fs::exists(here)) return here;
  return fs::path("experiments") / "plot" / name;
}

}  // namespace rearm::cli

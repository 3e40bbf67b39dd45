// Running the matplotlib scripts of experiments/plot from the command line.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rearm::cli {

// s quoted for /bin/sh.
std::string shell_quote(const std::string& s);

// The first python3 that imports every module of `modules`: $REARM_PYTHON, else python3 on
// PATH, else /usr/bin/python3 (Debian's, with python3-matplotlib and python3-pil from
// scripts/setup.sh); "" when none does.
std::string find_python(const std::vector<std::string>& modules);

// experiments/plot/<name>, found next to this source tree, else relative to the working
// directory.
std::filesystem::path plot_script(const std::string& name);

}  // namespace rearm::cli

#include "gpu/ShaderIncludes.h"

#include <algorithm>
#include <fstream>
#include <regex>

namespace firmament {

std::vector<std::string> shaderSourceFiles(const std::filesystem::path& root, const std::string& file) {
    static const std::regex includeLine(R"re(^\s*#\s*include\s*"([^"]+)")re");
    std::vector<std::string> files{file};
    for (size_t next = 0; next < files.size(); ++next) {
        std::ifstream in(root / files[next]);
        std::string line;
        std::smatch match;
        while (std::getline(in, line)) {
            if (!std::regex_search(line, match, includeLine)) continue;
            const std::string included = match[1].str();
            if (std::find(files.begin(), files.end(), included) == files.end()) files.push_back(included);
        }
    }
    return files;
}

}  // namespace firmament

// Where the assignments and their answers are, for the [assignments] and [student-kit] tests.
//
//   lectures/assignments/<nn>-<name>/starter.scene         what students start from
//   lectures/instructors/solutions/<nn>-<name>.scene       its reference solution
//   lectures/instructors/tried-answers/<nn>-<name>/*.scene answers tried on the grader, each
//                                                          with a "# Grade: PASS" or
//                                                          "# Grade: FAIL <first failure>" line
#pragma once

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace stepwise::test {

namespace fs = std::filesystem;

inline const fs::path kAssignments = fs::path(STEPWISE_SOURCE_DIR) / "lectures" / "assignments";
inline const fs::path kInstructors = fs::path(STEPWISE_SOURCE_DIR) / "lectures" / "instructors";
inline const fs::path kSolutions = kInstructors / "solutions";
inline const fs::path kTriedAnswers = kInstructors / "tried-answers";

inline std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// lectures/assignments/<nn>-<name>/ folders (those with a starter.scene), in order.
inline std::vector<fs::path> assignmentFolders() {
    std::vector<fs::path> folders;
    for (const fs::directory_entry& entry : fs::directory_iterator(kAssignments)) {
        if (entry.is_directory() && fs::exists(entry.path() / "starter.scene")) folders.push_back(entry.path());
    }
    std::sort(folders.begin(), folders.end());
    return folders;
}

/// Every regular file below @p folder, in order.
inline std::vector<fs::path> filesBelow(const fs::path& folder) {
    std::vector<fs::path> files;
    if (!fs::is_directory(folder)) return files;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(folder)) {
        if (entry.is_regular_file()) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace stepwise::test

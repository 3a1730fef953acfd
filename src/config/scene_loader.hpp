/// @file scene_loader.hpp
/// @brief Reads a scene file (docs/config-format.md) into a Scene, or says exactly what is wrong.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "world/scene.hpp"

namespace stepwise {

/// @brief One problem found in a scene file, located to the character.
struct ConfigDiagnostic {
    std::string file;      ///< Path as given (or the source name for text parsed from memory).
    int line = 0;          ///< 1-based line number.
    int column = 0;        ///< 1-based column of the offending token.
    std::string field;     ///< Field (or record) the problem is about, e.g. "Mass".
    std::string expected;  ///< What would have been accepted, e.g. "a number > 0".
    std::string found;     ///< What the file says there, e.g. "-2".
    std::string hint;      ///< Optional: "did you mean 'Elasticity'?", or how to fix it.

    /// @brief "file:line:column: error: <field>: expected …, found …; hint".
    std::string message() const;
};

/// @brief Thrown when a scene file cannot be loaded. Holds every problem found.
///
/// Loading is all-or-nothing: when this is thrown, no Scene was produced.
class ConfigError : public std::runtime_error {
public:
    /// @brief Builds the error from its diagnostics (at least one).
    explicit ConfigError(std::vector<ConfigDiagnostic> diagnostics);
    /// @brief Every problem, in file order.
    const std::vector<ConfigDiagnostic>& diagnostics() const { return diagnostics_; }

private:
    std::vector<ConfigDiagnostic> diagnostics_;
};

/// @brief What the loader may read besides the scene's own text.
struct SceneReadOptions {
    /// Read the OBJ files that `File=` names (relative to the folder of the scene's
    /// source name). Off, every File= is an error: the scene is then a function of its
    /// text alone, which the scene fuzzer needs (tests/fuzz/fuzz_oracles.hpp).
    bool readFiles = true;
};

/// @brief Parses scene text. @p sourceName is used in diagnostics and as Scene::sourcePath;
/// a `File=` path is read relative to its folder.
/// @throws ConfigError listing every problem found.
Scene parseScene(std::string_view text, const std::string& sourceName);

/// @brief Parses scene text, reading only what @p options allow.
/// @throws ConfigError listing every problem found.
Scene parseScene(std::string_view text, const std::string& sourceName, const SceneReadOptions& options);

/// @brief Reads and parses the scene file at @p path.
/// @throws ConfigError (also when the file cannot be opened, with line 0).
Scene loadSceneFile(const std::string& path);

}  // namespace stepwise

/// @file scene_changes.hpp
/// @brief What a submission changed against its starter, record by record and field by field.
///
/// An assignment's starter scene says, in `MayChange` records, which fields
/// a student may edit (docs/config-format.md, section "MayChange").
/// `stepwise grade --expect STARTER` then compares each submission with the
/// starter and fails every other change, so a student cannot reach the
/// target by moving something the assignment fixes (dropping the ball from
/// higher up instead of finding its elasticity).
///
/// The comparison reads both files as records, the way the loader does, and
/// compares what each line *says*, not how it is laid out:
///
///   - records are matched by type and name (ignoring case); the World
///     record is matched with the World record; Expect and MayChange
///     records are not compared (grading uses the starter's own);
///   - every field, and every component of a vector or colour, is compared
///     by value: `Position=(0, 2, 0)` and `PositionX=0, PositionY=2, PositionZ=0`
///     are the same, and so are `Integrator=Euler` and `Integrator=ExplicitEuler`;
///     spaces, comments, the order of the fields and positional or named
///     form do not matter;
///   - a field given in one file and left out of the other is a change,
///     even when the value given is the default: the rule is "do not touch
///     this line", which a student can check by eye.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "config/scene_loader.hpp"
#include "world/scene.hpp"

namespace stepwise {

/// @brief One difference between a starter scene and a submission.
struct SceneChange {
    std::string record;    ///< Record type: "DynamicObject", "World", …
    std::string object;    ///< The object's name, as the submission spells it (the starter's if removed); "" for World.
    std::string field;     ///< Field or component changed: "PositionY", "Elasticity"; "" when a whole record was added or removed.
    std::string before;    ///< The value as written in the starter; "" when the starter leaves it out.
    std::string after;     ///< The value as written in the submission; "" when the submission leaves it out.
    int line = 0;          ///< Line in the submission; 0 when the record is not there.
    int column = 0;        ///< Column of the value in the submission (of the record name when the value is left out).
    int starterLine = 0;   ///< Line of the record in the starter; 0 when it is not there.
    bool allowed = false;  ///< True when one of the starter's MayChange records names this field.
};

/// @brief Every difference between two scene texts, in the submission's line order (missing records last).
///
/// Both texts should load (the caller loads them first, to report their own
/// problems); a line that does not read is compared as far as it reads.
/// @param allowed the starter's MayChange records (Scene::mayChange), which set SceneChange::allowed.
std::vector<SceneChange> compareWithStarter(std::string_view starterText, std::string_view submissionText,
                                            std::span<const MayChange> allowed);

/// @brief "ball.Elasticity", "World.TimeStep": what a MayChange record allows, in words.
std::string describeAllowed(const MayChange& allowed);

/// @brief A change as a diagnostic, located like the loader's:
///        "bob.scene:13:35: error: ball.PositionY: expected 2.1, as in the starter (line 13), found '32.1'; …".
/// @param submissionPath the file the line and column are in.
/// @param allowed the starter's MayChange records, listed in the hint.
ConfigDiagnostic changeDiagnostic(const SceneChange& change, const std::string& submissionPath,
                                  std::span<const MayChange> allowed);

}  // namespace stepwise

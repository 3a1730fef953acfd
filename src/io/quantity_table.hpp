/// @file quantity_table.hpp
/// @brief One quantity of chosen bodies, sampled as a run goes: the numbers `stepwise plot` draws.
///
/// `stepwise run --csv` writes every body's whole state. A plot wants less
/// and more: one quantity, a few bodies, and quantities the state alone does
/// not give, such as the energy (it needs the mass, the inertia, the springs).
/// A QuantityTable holds such a selection, one column per body and component,
/// one row per sample:
///
///     time,ball:x,ball:y,ball:z
///     0,0,10,0
///     0.016666666666666666,0.050000000000000003,10.066666666666666,0
///
/// A column is named `BODY:COMPONENT`. Scene names are letters, digits, `_`,
/// `-` and `.` (docs/config-format.md, "Names"), so the colon cannot be part of
/// one, and `(all):COMPONENT` (the whole scene) cannot clash with a body.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "world/world.hpp"

namespace stepwise {

/// @brief What `stepwise plot --quantity` can draw.
enum class PlotQuantity {
    Position,         ///< Centre of mass x, m (dynamic or kinematic bodies).
    Velocity,         ///< v, m/s (dynamic or kinematic bodies).
    AngularVelocity,  ///< ω in the world frame, rad/s (dynamic or kinematic bodies).
    Momentum,         ///< p = m·v, kg·m/s (dynamic bodies).
    Energy,           ///< Kinetic and potential energy, J (dynamic bodies; energyOfBody()).
};

/// @brief The word of a quantity on the command line: "position", "velocity", "angular-velocity",
/// "momentum", "energy".
const char* toString(PlotQuantity quantity);

/// @brief The quantity named @p word (as toString() spells it); false when there is none.
bool parsePlotQuantity(std::string_view word, PlotQuantity& quantity);

/// @brief Every quantity's word, for messages: "position, velocity, angular-velocity, momentum, energy".
std::string plotQuantityWords();

/// @brief The components a quantity has, in order. Vectors: x, y, z and norm (the length).
/// Energy: translational (½·m·|v|²), rotational (½·ω·L), kinetic (their sum), potential, total.
const std::vector<std::string>& plotComponents(PlotQuantity quantity);

/// @brief The components drawn when none are asked for: x, y, z; for energy kinetic, potential, total.
std::vector<std::string> defaultPlotComponents(PlotQuantity quantity);

/// @brief The quantity's unit, as a plot's axis shows it: "m", "m/s", "rad/s", "kg m/s", "J".
const char* plotUnit(PlotQuantity quantity);

/// @brief Most bodies one plot draws: more lines than this are a tangle no one can read.
inline constexpr std::size_t kMaxPlottedBodies = 8;

/// @brief Name of the series that is the whole scene (columns `(all):COMPONENT`).
inline constexpr const char* kWholeSceneSeries = "(all)";

/// @brief One quantity of chosen bodies, a row per sample (see the file comment).
class QuantityTable {
public:
    /// @brief Chooses the series to sample from @p world.
    ///
    /// @param bodies the bodies' names, in the order to draw them; empty: every dynamic body,
    ///        and for momentum and energy of a scene with more than one dynamic body also the
    ///        whole scene (linearMomentumOf(), energyOf(world): springs between bodies included).
    ///        A scene of more than kMaxPlottedBodies dynamic bodies then gives the whole scene alone
    ///        for momentum and energy, and is an error for the other quantities.
    /// @param components the components to sample (plotComponents()); empty: the defaults.
    /// @throws std::invalid_argument naming the cause: a body the scene does not have, one named
    ///         twice, a kinematic body's momentum or energy (it has no mass), a component the
    ///         quantity does not have, too many bodies.
    QuantityTable(const World& world, PlotQuantity quantity, const std::vector<std::string>& bodies,
                  const std::vector<std::string>& components);

    PlotQuantity quantity() const { return quantity_; }  ///< What is sampled.
    /// @brief The series, in order: body names, and kWholeSceneSeries for the whole scene.
    const std::vector<std::string>& series() const { return seriesNames_; }
    const std::vector<std::string>& components() const { return components_; }  ///< The components sampled.
    /// @brief The column names after time: for each series, each component, "ball:y".
    std::vector<std::string> columnNames() const;

    /// @brief Appends a row: the world's time, then every series' components, in columnNames() order.
    void sample(const World& world);

    /// @brief The rows sampled so far: time first, then one number per column.
    const std::vector<std::vector<double>>& rows() const { return rows_; }

    /// @brief Writes the header (`time,` and the column names) and every row, 17 significant digits
    /// (enough to read back the exact double).
    void writeCsv(std::FILE* out) const;

private:
    struct Series {
        enum class Kind { Dynamic, Kinematic, WholeScene } kind = Kind::Dynamic;
        std::size_t index = 0;  ///< In the World's dynamic or kinematic array.
    };
    /// The value of component @p c of series @p s.
    double value(const World& world, const Series& s, std::size_t c) const;

    PlotQuantity quantity_;
    std::vector<Series> series_;
    std::vector<std::string> seriesNames_;
    std::vector<std::string> components_;
    std::vector<std::size_t> componentIndex_;  ///< Each component's place in plotComponents().
    std::vector<std::vector<double>> rows_;
};

}  // namespace stepwise

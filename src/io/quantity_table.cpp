/// @file quantity_table.cpp
/// @brief QuantityTable (quantity_table.hpp): the series of a plot, sampled.
#include "io/quantity_table.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "world/measurements.hpp"

namespace stepwise {

namespace {

constexpr PlotQuantity kQuantities[] = {PlotQuantity::Position, PlotQuantity::Velocity, PlotQuantity::AngularVelocity,
                                        PlotQuantity::Momentum, PlotQuantity::Energy};

/// Names compare as the scene loader compares them: ignoring case.
bool sameName(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

bool needsMass(PlotQuantity quantity) { return quantity == PlotQuantity::Momentum || quantity == PlotQuantity::Energy; }

/// Component @p c of a vector: x, y, z, then the norm.
double componentOf(const Vec3& v, std::size_t c) { return c < 3 ? double(v[static_cast<int>(c)]) : double(glm::length(v)); }

/// Component @p c of an energy, in plotComponents(Energy)'s order.
double componentOf(const Energy& e, std::size_t c) {
    const Real parts[] = {e.translational, e.rotational, e.kinetic, e.potential, e.total()};
    return double(parts[c]);
}

}  // namespace

const char* toString(PlotQuantity quantity) {
    switch (quantity) {
        case PlotQuantity::Position: return "position";
        case PlotQuantity::Velocity: return "velocity";
        case PlotQuantity::AngularVelocity: return "angular-velocity";
        case PlotQuantity::Momentum: return "momentum";
        case PlotQuantity::Energy: return "energy";
    }
    return "?";
}

bool parsePlotQuantity(std::string_view word, PlotQuantity& quantity) {
    for (const PlotQuantity q : kQuantities) {
        if (sameName(word, toString(q))) {
            quantity = q;
            return true;
        }
    }
    return false;
}

std::string plotQuantityWords() {
    std::string words;
    for (const PlotQuantity q : kQuantities) words += (words.empty() ? "" : ", ") + std::string(toString(q));
    return words;
}

const std::vector<std::string>& plotComponents(PlotQuantity quantity) {
    static const std::vector<std::string> vector = {"x", "y", "z", "norm"};
    static const std::vector<std::string> energy = {"translational", "rotational", "kinetic", "potential", "total"};
    return quantity == PlotQuantity::Energy ? energy : vector;
}

std::vector<std::string> defaultPlotComponents(PlotQuantity quantity) {
    if (quantity == PlotQuantity::Energy) return {"kinetic", "potential", "total"};
    return {"x", "y", "z"};
}

const char* plotUnit(PlotQuantity quantity) {
    switch (quantity) {
        case PlotQuantity::Position: return "m";
        case PlotQuantity::Velocity: return "m/s";
        case PlotQuantity::AngularVelocity: return "rad/s";
        case PlotQuantity::Momentum: return "kg m/s";
        case PlotQuantity::Energy: return "J";
    }
    return "";
}

QuantityTable::QuantityTable(const World& world, PlotQuantity quantity, const std::vector<std::string>& bodies,
                             const std::vector<std::string>& components)
    : quantity_(quantity) {
    const std::vector<DynamicObject>& dynamics = world.dynamics();
    if (bodies.empty()) {
        const bool wholeScene = needsMass(quantity) && dynamics.size() > 1;
        if (dynamics.size() > kMaxPlottedBodies && !wholeScene) {
            throw std::invalid_argument("the scene has " + std::to_string(dynamics.size()) +
                                        " dynamic bodies, too many lines for one plot: choose up to " +
                                        std::to_string(kMaxPlottedBodies) + " with --object NAME");
        }
        if (dynamics.empty()) {
            throw std::invalid_argument("the scene has no dynamic body to plot" +
                                        std::string(needsMass(quantity) ? "" : ": name a kinematic one with --object NAME"));
        }
        if (dynamics.size() <= kMaxPlottedBodies) {
            for (std::size_t i = 0; i < dynamics.size(); ++i) {
                series_.push_back({Series::Kind::Dynamic, i});
                seriesNames_.push_back(dynamics[i].name);
            }
        }
        if (wholeScene) {
            series_.push_back({Series::Kind::WholeScene, 0});
            seriesNames_.push_back(kWholeSceneSeries);
        }
    } else {
        if (bodies.size() > kMaxPlottedBodies) {
            throw std::invalid_argument(std::to_string(bodies.size()) + " bodies named with --object: one plot draws at most " +
                                        std::to_string(kMaxPlottedBodies));
        }
        for (const std::string& name : bodies) {
            Series found;
            bool known = false;
            for (std::size_t i = 0; i < dynamics.size() && !known; ++i) {
                if (sameName(dynamics[i].name, name)) {
                    found = {Series::Kind::Dynamic, i};
                    known = true;
                }
            }
            for (std::size_t i = 0; i < world.kinematics().size() && !known; ++i) {
                if (sameName(world.kinematics()[i].name, name)) {
                    found = {Series::Kind::Kinematic, i};
                    known = true;
                }
            }
            if (!known) {
                const bool plane = std::any_of(world.planes().begin(), world.planes().end(),
                                               [&](const CollisionPlane& p) { return sameName(p.name, name); });
                throw std::invalid_argument(plane ? "'" + name + "' is a collision plane: it never moves, there is nothing to plot"
                                                  : "the scene has no body named '" + name + "'");
            }
            if (found.kind == Series::Kind::Kinematic && needsMass(quantity)) {
                throw std::invalid_argument("'" + name + "' is a kinematic body: it has no mass, so no " +
                                            toString(quantity) + " (plot its position or velocity)");
            }
            const std::string& canonical =
                found.kind == Series::Kind::Dynamic ? dynamics[found.index].name : world.kinematics()[found.index].name;
            if (std::find(seriesNames_.begin(), seriesNames_.end(), canonical) != seriesNames_.end()) {
                throw std::invalid_argument("'" + name + "' is named twice with --object");
            }
            series_.push_back(found);
            seriesNames_.push_back(canonical);
        }
    }

    const std::vector<std::string>& known = plotComponents(quantity);
    components_ = components.empty() ? defaultPlotComponents(quantity) : components;
    for (const std::string& component : components_) {
        const auto at = std::find(known.begin(), known.end(), component);
        if (at == known.end()) {
            std::string list;
            for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
            throw std::invalid_argument(std::string(toString(quantity)) + " has no component '" + component +
                                        "' (it has " + list + ")");
        }
        if (std::count(components_.begin(), components_.end(), component) > 1) {
            throw std::invalid_argument("component '" + component + "' is asked for twice");
        }
        componentIndex_.push_back(static_cast<std::size_t>(at - known.begin()));
    }
}

std::vector<std::string> QuantityTable::columnNames() const {
    std::vector<std::string> names;
    for (const std::string& series : seriesNames_) {
        for (const std::string& component : components_) names.push_back(series + ":" + component);
    }
    return names;
}

double QuantityTable::value(const World& world, const Series& s, std::size_t c) const {
    if (s.kind == Series::Kind::WholeScene) {
        return quantity_ == PlotQuantity::Energy ? componentOf(energyOf(world), c) : componentOf(linearMomentumOf(world), c);
    }
    const bool kinematic = s.kind == Series::Kind::Kinematic;
    const GameObject& object = kinematic ? static_cast<const GameObject&>(world.kinematics()[s.index])
                                         : static_cast<const GameObject&>(world.dynamics()[s.index]);
    const Vec3& velocity = kinematic ? world.kinematics()[s.index].velocity : world.dynamics()[s.index].velocity;
    const Vec3& omega = kinematic ? world.kinematics()[s.index].angularVelocity : world.dynamics()[s.index].angularVelocity;
    switch (quantity_) {
        case PlotQuantity::Position: return componentOf(object.position, c);
        case PlotQuantity::Velocity: return componentOf(velocity, c);
        case PlotQuantity::AngularVelocity: return componentOf(omega, c);
        case PlotQuantity::Momentum: return componentOf(world.dynamics()[s.index].mass * velocity, c);
        case PlotQuantity::Energy: return componentOf(energyOfBody(world, s.index), c);
    }
    return 0;
}

void QuantityTable::sample(const World& world) {
    std::vector<double> row;
    row.reserve(1 + series_.size() * componentIndex_.size());
    row.push_back(double(world.time()));
    for (const Series& s : series_) {
        for (const std::size_t c : componentIndex_) row.push_back(value(world, s, c));
    }
    rows_.push_back(std::move(row));
}

void QuantityTable::writeCsv(std::FILE* out) const {
    std::fprintf(out, "time");
    for (const std::string& name : columnNames()) std::fprintf(out, ",%s", name.c_str());
    std::fprintf(out, "\n");
    for (const std::vector<double>& row : rows_) {
        for (std::size_t i = 0; i < row.size(); ++i) std::fprintf(out, i == 0 ? "%.17g" : ",%.17g", row[i]);
        std::fprintf(out, "\n");
    }
}

}  // namespace stepwise

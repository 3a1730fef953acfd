/// @file overlay.cpp
/// @brief The 2D text layer, drawn with GLUT's bitmap font in an orthographic projection.
#include "viewer/overlay.hpp"
#include "viewer/view_options.hpp"

#include <GL/freeglut.h>

#include <algorithm>
#include <iterator>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "world/measurements.hpp"
#include "world/step_plan.hpp"

namespace stepwise::viewer {

namespace {

/// GLUT's fixed-width 8×13 font: every character is 8 pixels wide.
void* const kFont = GLUT_BITMAP_8_BY_13;
constexpr int kCharWidth = 8;
constexpr int kLineHeight = 15;
constexpr int kMargin = 8;

/// Short stage names for the one-line timing table.
constexpr const char* kShortStageNames[kStageCount] = {"forces",  "integrate", "kinematics", "broad",   "narrow",
                                                       "impulses", "positions", "prepare",   "solve",   "relax",
                                                       "bounce",   "sleep",     "ccd",       "soft"};

std::string format(const char* pattern, double a, double b = 0, double c = 0) {
    char text[200];
    std::snprintf(text, sizeof text, pattern, a, b, c);
    return text;
}

std::string vec(const Vec3& v) { return format("(%.3g, %.3g, %.3g)", double(v.x), double(v.y), double(v.z)); }

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

/// Breaks lines longer than @p maxChars, continuing them indented on the next line.
std::vector<std::string> wrap(const std::vector<std::string>& lines, int maxChars) {
    const std::size_t limit = static_cast<std::size_t>(std::max(maxChars, 20));
    std::vector<std::string> wrapped;
    for (const std::string& line : lines) {
        std::string rest = line;
        while (rest.size() > limit) {
            std::size_t cut = rest.rfind(' ', limit);
            if (cut == std::string::npos || cut < limit / 2) cut = limit;
            wrapped.push_back(rest.substr(0, cut));
            rest = "    " + rest.substr(rest[cut] == ' ' ? cut + 1 : cut);
        }
        wrapped.push_back(rest);
    }
    return wrapped;
}

/// Width in pixels of the panel that holds @p lines.
int panelWidth(const std::vector<std::string>& lines) {
    std::size_t widest = 0;
    for (const std::string& line : lines) widest = std::max(widest, line.size());
    return static_cast<int>(widest) * kCharWidth + 2 * kMargin;
}

/// The text's colour: near-white (the screenshot test looks for it).
constexpr Color kTextColor{0.95f, 0.95f, 0.95f};

/// A translucent panel with lines of text; (x, y) is its top-left corner in
/// pixels from the window's top-left. @p colours, when given, has one text colour per line.
void panel(int x, int y, const std::vector<std::string>& lines, float r, float g, float b, float alpha = 0.6f,
           const std::vector<Color>* colours = nullptr) {
    if (lines.empty()) return;
    const int w = panelWidth(lines);
    const int h = static_cast<int>(lines.size()) * kLineHeight + kMargin;
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4f(r, g, b, alpha);
    glBegin(GL_QUADS);
    glVertex2i(x, y);
    glVertex2i(x + w, y);
    glVertex2i(x + w, y + h);
    glVertex2i(x, y + h);
    glEnd();
    glDisable(GL_BLEND);
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const Color& c = colours && i < colours->size() ? (*colours)[i] : kTextColor;
        glColor3f(c.r, c.g, c.b);  // before glRasterPos: the position takes the current colour
        glRasterPos2i(x + kMargin, y + kMargin / 2 + static_cast<int>(i + 1) * kLineHeight - 4);
        glutBitmapString(kFont, reinterpret_cast<const unsigned char*>(lines[i].c_str()));
    }
}

/// The S panel: where in the step the shown snapshot is, what its stage
/// produced, and the keys. The pipeline line lists the step's stages in the
/// order they ran, the substep loop as one item, the shown one in brackets.
std::vector<std::string> walkthroughLines(const Simulation& simulation) {
    const StageWalkthrough& walk = simulation.walkthrough();
    const std::size_t shown = *simulation.shownStage();
    const StageSnapshot& now = walk.snapshot(shown);
    std::vector<std::string> lines;
    lines.push_back(format("S: step %.0f, stage run %.0f of %.0f", double(now.event.step), double(shown + 1),
                           double(walk.size())) +
                    format(" (the step ran once; the state after each stage, as captured: %.0f KB)",
                           double(walk.memoryBytes()) / 1024.0));
    std::string pipeline = "  ";
    bool inLoop = false;
    for (std::size_t k = 0; k < walk.size(); ++k) {
        const StageEvent& e = walk.snapshot(k).event;
        if (e.substep >= 0 && inLoop) continue;
        inLoop = e.substep >= 0;
        if (k > 0) pipeline += " > ";
        if (inLoop) {
            pipeline += now.event.substep >= 0 ? format("[substep %.0f/%.0f: ", double(now.event.substep + 1),
                                                        double(now.event.substeps)) +
                                                     stageName(now.event.stage) + "]"
                                               : format("substeps x%.0f", double(e.substeps));
        } else {
            pipeline += k == shown ? std::string("[") + stageName(e.stage) + "]" : std::string(stageName(e.stage));
        }
    }
    lines.push_back(pipeline);
    lines.push_back(" > " + now.description + format("  [%.1f us]", 1e6 * now.seconds));
    lines.push_back("   white outlines: the bodies at the start of the step.  S: next stage  Shift+S: skip the "
                    "middle substeps  N: end of the step  Space: run");
    return lines;
}

/// The heads-up display's last line: the drawings switched on, and what the mouse points at.
std::string togglesLine(const OverlayState& state) {
    std::string toggles = "H help";
    if (state.draw.contacts) toggles += "   C contacts";
    if (state.draw.velocities) toggles += "   V velocities";
    if (state.draw.boundingBoxes) toggles += "   B bounding boxes";
    if (!state.pointed.empty()) toggles += "   " + state.pointed;
    return toggles;
}

/// Height above a space's swept box at which its name is drawn, m.
constexpr Real kNameHeight = Real(0.3);

/// The spaces' names, from @p top down (below the heads-up display): side by side, each above its
/// space (or at @p top, in its space's column, when above would be under the display); overlaid, a
/// legend at the right.
void spaceNames(const Simulation& simulation, const OrbitCamera& camera, int width, int height, int top) {
    const SpaceLayout& layout = simulation.layout();
    const std::vector<Space>& spaces = simulation.spaces()->all();
    if (layout.arrangement() == SpaceArrangement::Overlaid) {
        std::vector<std::string> lines;
        std::vector<Color> colours;
        for (std::size_t k = 0; k < spaces.size(); ++k) {
            lines.push_back(std::to_string(k + 1) + " " + spaces[k].name + (spaces[k].paused ? " (paused)" : ""));
            colours.push_back(spaceColor(k));
        }
        panel(width - panelWidth(lines) - kMargin, top, lines, 0.0f, 0.0f, 0.0f, 0.6f, &colours);
        return;
    }
    for (std::size_t k = 0; k < spaces.size(); ++k) {
        const Aabb box = layout.bounds(k);
        const Vec3 above = Vec3((box.min.x + box.max.x) / 2, box.max.y + kNameHeight, (box.min.z + box.max.z) / 2) +
                         layout.offset(k);
        const Vec3 pixel = camera.project(above, width, height);
        if (!(pixel.z > 0 && pixel.z < 1)) continue;  // behind the eye
        const std::vector<std::string> name{spaces[k].name + (spaces[k].paused ? " (paused)" : "")};
        const std::vector<Color> colour{spaceColor(k)};
        const int x = static_cast<int>(pixel.x) - panelWidth(name) / 2;
        const int y = std::max(top, static_cast<int>(pixel.y) - kLineHeight - kMargin);
        panel(x, y, name, 0.0f, 0.0f, 0.0f, 0.45f, &colour);
    }
}

}  // namespace

std::vector<std::string> helpLines() { return {std::begin(kViewerControls), std::end(kViewerControls)}; }

std::string spaceLine(const Simulation& simulation, std::size_t k) {
    const Space& space = simulation.spaces()->all()[k];
    const World& world = space.world;
    const WorldSettings& s = world.settings();
    std::string line = std::to_string(k + 1) + " " + space.name +
                       format(": t = %.3f s  step %.0f  h = %.4g s  ", double(world.time()),
                              double(world.stepCount()), double(s.timeStep)) +
                       toString(s.integrator) + ", " + toString(s.solver);
    if (space.timeScale != 1) line += format("  x%.3g", double(space.timeScale));
    line += "  bodies " + std::to_string(world.dynamics().size());
    if (!world.softBodies().empty()) line += "  soft " + std::to_string(world.softBodies().size());
    line += "  contacts " +
            std::to_string(world.contacts().size()) + format("  energy %.6g J", double(energyOf(world).total()));
    if (space.paused) line += "  PAUSED";
    return line;
}

std::vector<std::string> hudLines(const Simulation& simulation, const OverlayState& state) {
    const World& world = simulation.world();
    const FixedStepClock& clock = simulation.clock();
    std::vector<std::string> lines;

    if (const Spaces* spaces = simulation.spaces()) {
        // One shared clock; each space's own time, step and pace on its line (src/world/spaces.hpp).
        std::string first = std::filesystem::path(simulation.scenePath()).filename().string() +
                            format("  clock t = %.3f s (ticks of %.4g s)", double(spaces->clock()),
                                   double(spaces->finestTick()));
        first += clock.paused() ? "  PAUSED" : format("  running x%.3g", clock.scale());
        if (state.framesPerSecond > 0) first += format("  %.0f fps", state.framesPerSecond);
        lines.push_back(first);
        lines.push_back(simulation.layout().arrangement() == SpaceArrangement::SideBySide
                                ? "spaces side by side (L: overlaid)   1-9: pause / resume a space"
                                : "spaces overlaid, each in its colour (L: side by side)   1-9: pause / resume a space");
        for (std::size_t k = 0; k < spaces->all().size(); ++k) lines.push_back(spaceLine(simulation, k));
        lines.push_back(togglesLine(state));
        return lines;
    }

    // "step N" is the last step taken: steps count from 1, so after N steps stepCount() is N and
    // t = N·h, and the S panel's "step N" (StageEvent::step) is the same step (architecture.md, "Step numbers").
    std::string first = std::filesystem::path(simulation.scenePath()).filename().string() +
                        format("  t = %.3f s  step %.0f  h = %.4g s", double(world.time()),
                               double(world.stepCount()), double(world.settings().timeStep));
    first += clock.paused() ? "  PAUSED" : format("  running x%.3g", clock.scale());
    if (state.framesPerSecond > 0) first += format("  %.0f fps", state.framesPerSecond);
    lines.push_back(first);

    const auto asleep = static_cast<std::size_t>(std::count_if(
        world.dynamics().begin(), world.dynamics().end(), [](const DynamicObject& b) { return b.asleep; }));
    std::string soft;  // soft bodies sleep as rigid ones do (src/dynamics/islands.hpp)
    if (!world.softBodies().empty()) {
        const auto softAsleep = static_cast<std::size_t>(std::count_if(
            world.softBodies().begin(), world.softBodies().end(), [](const SoftBody& b) { return b.asleep; }));
        soft = "; soft: " + std::to_string(world.softBodies().size() - softAsleep) + " awake, " +
               std::to_string(softAsleep) + " asleep";
    }
    lines.push_back("bodies: " + std::to_string(world.dynamics().size() - asleep) + " awake, " +
                    std::to_string(asleep) + " asleep; " + std::to_string(world.kinematics().size()) +
                    " kinematic, " + std::to_string(world.planes().size()) + " planes" + soft);
    lines.push_back("contacts " + std::to_string(world.contacts().size()) + "   candidate pairs " +
                    std::to_string(world.candidatePairs().size()));

    const Energy e = energyOf(world);
    lines.push_back(format("energy %.6g J (kinetic %.4g, potential %.4g)", double(e.total()), double(e.kinetic),
                           double(e.potential)));
    lines.push_back("momentum " + vec(linearMomentumOf(world)) + " kg*m/s   L " + vec(angularMomentumOf(world)) +
                    " kg*m^2/s");

    std::string timing = "last step, us:";
    for (std::size_t i = 0; i < kStageCount; ++i) {
        const StageRecord& r = world.stageRecords()[i];
        if (i == 4) {  // two lines, so the display fits a narrow window
            lines.push_back(timing);
            timing = "             ";
        }
        timing += std::string(" ") + kShortStageNames[i] + format(" %.1f", 1e6 * r.lastSeconds);
    }
    lines.push_back(timing);
    lines.push_back(skippedStagesLine(world.plan(), world.stageRecords(), world.stepCount() > 0));

    lines.push_back(togglesLine(state));
    return lines;
}

void drawOverlay(const Simulation& simulation, const OrbitCamera& camera, int width, int height,
                 const OverlayState& state) {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, width, height, 0, -1, 1);  // y grows downwards, like window coordinates
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_LIGHTING);

    // Every panel is wrapped to the window's width, so that nothing (an error above all) is cut off.
    const int maxChars = (width - 4 * kMargin) / kCharWidth;
    int y = kMargin;
    if (state.hud) {
        const std::vector<std::string> lines = wrap(hudLines(simulation, state), maxChars);
        const int below = y + static_cast<int>(lines.size()) * kLineHeight + 2 * kMargin;
        panel(kMargin, y, lines, 0.0f, 0.0f, 0.0f, 0.55f);
        if (simulation.hasSpaces()) spaceNames(simulation, camera, width, height, below);
        y = below;
    }

    if (state.help) panel(kMargin, y, wrap(helpLines(), maxChars), 0.0f, 0.0f, 0.0f, 0.7f);

    // From the bottom up: the stage walk-through, then notices and errors above it.
    int bottom = height - kMargin;
    auto panelAbove = [&](const std::vector<std::string>& lines, float r, float g, float b, float alpha) {
        if (lines.empty()) return;
        bottom -= static_cast<int>(lines.size()) * kLineHeight + kMargin;
        panel(kMargin, bottom, lines, r, g, b, alpha);
        bottom -= kMargin;
    };
    if (simulation.shownStage()) panelAbove(wrap(walkthroughLines(simulation), maxChars), 0.05f, 0.15f, 0.35f, 0.7f);
    std::vector<std::string> notices;
    if (!state.message.empty()) notices.push_back(state.message);
    if (!simulation.error().empty()) {
        for (const std::string& line : splitLines(simulation.error())) notices.push_back(line);
    }
    const bool isError = !simulation.error().empty();
    panelAbove(wrap(notices, maxChars), isError ? 0.45f : 0.0f, 0.0f, 0.0f, 0.75f);
    glEnable(GL_DEPTH_TEST);
}

}  // namespace stepwise::viewer

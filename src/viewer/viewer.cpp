/// @file viewer.cpp
/// @brief The freeglut application: window, callbacks, controls, picking, screenshots.
#include "viewer/viewer.hpp"

#include <GL/freeglut.h>

#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <stdexcept>

#if defined(__SANITIZE_ADDRESS__)
#include <dlfcn.h>
#include <link.h>
#endif

#include "config/scene_loader.hpp"
#include "core/errors.hpp"
#include "core/exit_codes.hpp"
#include "viewer/camera.hpp"
#include "viewer/display_check.hpp"
#include "viewer/event_log.hpp"
#include "viewer/mouse_controls.hpp"
#include "viewer/overlay.hpp"
#include "viewer/picking.hpp"
#include "viewer/png_writer.hpp"
#include "viewer/renderer.hpp"
#include "viewer/simulation.hpp"

namespace stepwise::viewer {

namespace {

using Clock = std::chrono::steady_clock;

/// Milliseconds between redraws (about 60 frames per second). A timer, not
/// an idle callback, so a paused viewer does not spin a CPU core.
constexpr unsigned kFrameMilliseconds = 16;
/// Seconds a notice (reloaded, not available yet, …) stays on screen.
constexpr double kMessageSeconds = 4.0;
/// GLUT's numbers for the X11 wheel "buttons" (freeglut has no names for them).
constexpr int kGlutWheelUp = 3;
constexpr int kGlutWheelDown = 4;

/// Everything the GLUT callbacks share. GLUT's callbacks are plain functions
/// without a user pointer, so the one instance is reached through `app`.
struct App {
    std::unique_ptr<Simulation> simulation;
    OrbitCamera camera;
    OverlayState overlay;
    int width = 960;
    int height = 600;

    Drag drag = Drag::None;
    int mouseX = 0;
    int mouseY = 0;
    bool pointerInside = false;  // the pointer is in the window (GLUT reports entering and leaving)

    Clock::time_point lastFrame = Clock::now();
    Clock::time_point messageShown = Clock::now();
    Clock::time_point fpsStart = Clock::now();
    int fpsFrames = 0;

    // Screenshot mode.
    bool screenshot = false;
    std::string screenshotPath;
    std::string dumpStatePath;
    int exitCode = kExitOk;

    EventLog log;  // --log-events; writes nothing without it
    std::string highlighted = "none";  // last body named in a "highlight" line
};

App* app = nullptr;

void notify(const std::string& message) {
    app->overlay.message = message;
    app->messageShown = Clock::now();
}

Ray mouseRay(int x, int y) {
    return app->camera.rayThroughPixel(Real(x) + Real(0.5), Real(y) + Real(0.5), app->width, app->height);
}

/// The body under pixel (x, y), in whichever space, or nothing.
std::optional<SpaceHit> pickAt(int x, int y) { return pickInSimulation(*app->simulation, mouseRay(x, y)); }

/// The camera that frames the scene in a @p width × @p height window: its bodies, or every space as drawn
/// (F, L, and at the start).
OrbitCamera frameScene(const Simulation& sim, int width, int height) {
    return sim.hasSpaces() ? cameraForSpaces(sim.layout(), Real(width) / Real(height)) : cameraForScene(sim.world());
}

/// The name shown for what the mouse points at or holds.
void describePointer(const std::optional<SpaceHit>& hit) {
    const Simulation& sim = *app->simulation;
    if (const std::optional<Grab>& grab = sim.grabbed()) {
        const World& world = sim.worldAt(sim.grabbedSpace());
        app->overlay.pointed = std::string(grab->pull ? "pulling " : "pushing ") + world.dynamics()[grab->body].name;
        app->overlay.draw.hovered = BodyRef{BodyKind::Dynamic, grab->body};
        app->overlay.draw.hoveredSpace = sim.grabbedSpace();
    } else if (hit && hit->hit.body.kind != BodyKind::Plane) {
        const BodyRef ref = hit->hit.body;
        app->overlay.pointed = "pointing at " + bodyName(sim.worldAt(hit->space), ref) +
                               (sim.hasSpaces() ? " in space " + sim.spaces()->all()[hit->space].name : "") +
                               (ref.kind == BodyKind::Kinematic ? " (kinematic: cannot be pushed)" : "");
        app->overlay.draw.hovered = ref;
        app->overlay.draw.hoveredSpace = hit->space;
    } else {
        app->overlay.pointed.clear();
        app->overlay.draw.hovered.reset();
    }
    const std::string highlighted =
        app->overlay.draw.hovered ? bodyName(sim.worldAt(app->overlay.draw.hoveredSpace), *app->overlay.draw.hovered)
                                  : std::string("none");
    if (highlighted != app->highlighted) {
        app->highlighted = highlighted;
        app->log.line("highlight %s", highlighted.c_str());
    }
}

void savePicture();  // the P key, below: it draws, so it comes after drawFrame()

/// One key press: shared by the keyboard callback and `--keys`.
void pressKey(unsigned char key) {
    Simulation& sim = *app->simulation;
    FixedStepClock& clock = sim.clock();
    switch (key) {
        case 27:
        case 'q':
        case 'Q':
            if (!app->screenshot) glutLeaveMainLoop();
            break;
        case ' ':
            clock.setPaused(!clock.paused());
            if (!clock.paused()) sim.clearError();
            break;
        case 'n':
        case 'N':
            clock.setPaused(true);
            if (!sim.stepOnce()) notify("N: every space is paused (1-9 resume one)");
            break;
        case 's':
        case 'S':
            if (sim.hasSpaces()) notify(std::string("S: ") + kNoWalkthroughWithSpaces);
            else sim.stepStage(key == 'S');  // Shift+S: past the middle substeps
            break;
        case 'l':
        case 'L':
            if (!sim.hasSpaces()) {
                notify("L: this scene has no spaces (Space records) to arrange");
                break;
            }
            sim.layout().arrange(sim.layout().arrangement() == SpaceArrangement::SideBySide
                                         ? SpaceArrangement::Overlaid
                                         : SpaceArrangement::SideBySide);
            app->camera = frameScene(sim, app->width, app->height);  // the heads-up display names the arrangement
            break;
        case '+':
        case '=':
            clock.setScale(clock.scale() * 2);
            notify("time scale x" + std::to_string(clock.scale()).substr(0, 5));
            break;
        case '-':
        case '_':
            clock.setScale(clock.scale() / 2);
            notify("time scale x" + std::to_string(clock.scale()).substr(0, 5));
            break;
        case 'r':
        case 'R':
            if (sim.reload()) notify("R: reloaded " + sim.scenePath() + " (t = 0)");
            else notify("");
            app->drag = app->drag == Drag::Grab ? Drag::None : app->drag;
            describePointer(std::nullopt);
            break;
        case 'c':
        case 'C': app->overlay.draw.contacts = !app->overlay.draw.contacts; break;
        case 'v':
        case 'V': app->overlay.draw.velocities = !app->overlay.draw.velocities; break;
        case 'b':
        case 'B': app->overlay.draw.boundingBoxes = !app->overlay.draw.boundingBoxes; break;
        case 'i':
        case 'I': app->overlay.draw.islands = !app->overlay.draw.islands; break;
        case 'h':
        case 'H': app->overlay.help = !app->overlay.help; break;
        case 'f':
        case 'F': app->camera = frameScene(sim, app->width, app->height); break;
        case 'o':
        case 'O': app->overlay.hud = !app->overlay.hud; break;
        case 'p':
        case 'P':
            if (!app->screenshot) savePicture();  // a --screenshot is a picture already
            break;
        default:
            // 1-9: a space's pause, which its line of the heads-up display and its name show. A key
            // past the last space says so. A scene without spaces has no use for them: they do nothing.
            if (const std::optional<std::size_t> k = spaceForKey(key); k && sim.hasSpaces()) {
                if (!sim.toggleSpacePause(*k)) {
                    notify(std::string(1, char(key)) + ": there is no space " + std::string(1, char(key)) +
                           " (this scene has " + std::to_string(sim.worldCount()) + ")");
                }
            }
            break;
    }
}

void drawFrame(double framesPerSecond) {
    app->overlay.framesPerSecond = framesPerSecond;
    drawScene(*app->simulation, app->camera, app->width, app->height, app->overlay.draw);
    drawOverlay(*app->simulation, app->camera, app->width, app->height, app->overlay);
}

/// Draws a frame into the back buffer and writes it to the PNG file @p path,
/// reading it back before any buffer swap (so the window shows nothing new).
/// @throws std::runtime_error when the file cannot be written.
void writeFrame(const std::string& path, double framesPerSecond) {
    drawFrame(framesPerSecond);
    glFinish();
    const int width = app->width;
    const int height = app->height;
    std::vector<std::uint8_t> bottomUp(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, bottomUp.data());
    // OpenGL's rows start at the bottom, PNG's at the top.
    std::vector<std::uint8_t> topDown(bottomUp.size());
    const std::size_t row = static_cast<std::size_t>(width) * 3;
    for (std::size_t y = 0; y < static_cast<std::size_t>(height); ++y) {
        std::copy_n(bottomUp.begin() + static_cast<std::ptrdiff_t>(y * row), row,
                    topDown.begin() + static_cast<std::ptrdiff_t>((static_cast<std::size_t>(height) - 1 - y) * row));
    }
    writePng(path, width, height, topDown);
}

/// The P key: a picture of the window as it is now, in the current directory,
/// named after the scene and the step (`stepwise-NAME-stepN.png`, then
/// `stepwise-NAME-stepN-2.png`, … so that no earlier picture is overwritten).
/// With spaces, N counts the ticks of the shared clock.
void savePicture() {
    const Simulation& sim = *app->simulation;
    const std::uint64_t step = sim.hasSpaces() ? static_cast<std::uint64_t>(std::llround(
                                                       double(sim.spaces()->clock() / sim.spaces()->finestTick())))
                                               : sim.world().stepCount();
    const std::string stem =
        "stepwise-" + std::filesystem::path(sim.scenePath()).stem().string() + "-step" + std::to_string(step);
    std::string path = stem + ".png";
    for (int copy = 2; std::filesystem::exists(path); ++copy) path = stem + "-" + std::to_string(copy) + ".png";
    try {
        writeFrame(path, app->overlay.framesPerSecond);
        const double time = sim.hasSpaces() ? double(sim.spaces()->clock()) : double(sim.world().time());
        std::printf("Picture of the window at t = %.6g s written to %s\n", time, path.c_str());
        std::fflush(stdout);
        app->log.line("picture %s", path.c_str());
        notify("P: saved " + path);
    } catch (const std::runtime_error& e) {
        std::fprintf(stderr, "stepwise view: %s\n", e.what());
        notify(std::string("P: ") + e.what());
    }
}

// ---- Interactive callbacks -------------------------------------------------

void onDisplay() {
    const Clock::time_point now = Clock::now();
    const double frame = std::chrono::duration<double>(now - app->lastFrame).count();
    app->lastFrame = now;
    app->simulation->advanceFrame(frame);
    if (app->drag == Drag::Grab) app->simulation->aimGrab(mouseRay(app->mouseX, app->mouseY).direction);
    // Bodies move under a still cursor: pick again every frame, so the
    // outline is always on the body under the cursor now.
    if (app->pointerInside) describePointer(pickAt(app->mouseX, app->mouseY));
    if (!app->overlay.message.empty() &&
        std::chrono::duration<double>(now - app->messageShown).count() > kMessageSeconds) {
        app->overlay.message.clear();
    }

    ++app->fpsFrames;
    static double fps = 0;
    const double since = std::chrono::duration<double>(now - app->fpsStart).count();
    if (since >= 1.0) {
        fps = app->fpsFrames / since;
        app->fpsFrames = 0;
        app->fpsStart = now;
    }
    drawFrame(fps);
    glutSwapBuffers();
}

void onTimer(int) {
    glutPostRedisplay();
    glutTimerFunc(kFrameMilliseconds, onTimer, 0);
}

void onReshape(int width, int height) {
    app->width = std::max(1, width);
    app->height = std::max(1, height);
}

void onKeyboard(unsigned char key, int, int) { pressKey(key); }

/// GLUT's button code as a MouseButton; nothing for buttons the viewer does not use.
std::optional<MouseButton> mouseButton(int button) {
    switch (button) {
        case GLUT_LEFT_BUTTON: return MouseButton::Left;
        case GLUT_MIDDLE_BUTTON: return MouseButton::Middle;
        case GLUT_RIGHT_BUTTON: return MouseButton::Right;
        case kGlutWheelUp: return MouseButton::WheelUp;
        case kGlutWheelDown: return MouseButton::WheelDown;
        default: return std::nullopt;
    }
}

/// A "pick" line of the event log for a press at pixel (x, y); the hit point in its space's coordinates.
void logPick(const std::optional<SpaceHit>& hit, int x, int y) {
    if (!hit) {
        app->log.line("pick none pixel %d %d", x, y);
        return;
    }
    static constexpr const char* kKindNames[] = {"dynamic", "kinematic", "plane"};
    app->log.line("pick %s pixel %d %d hit %s %s",
                  bodyName(app->simulation->worldAt(hit->space), hit->hit.body).c_str(), x, y,
                  EventLog::vec(hit->hit.point).c_str(), kKindNames[static_cast<int>(hit->hit.body.kind)]);
}

void onMouse(int button, int state, int x, int y) {
    app->mouseX = x;
    app->mouseY = y;
    app->pointerInside = true;
    const std::optional<MouseButton> which = mouseButton(button);
    if (!which) return;
    if (state == GLUT_UP) {
        if (app->drag == Drag::Grab) app->simulation->release();
        app->drag = Drag::None;
        describePointer(pickAt(x, y));
        return;
    }
    if (*which == MouseButton::WheelUp || *which == MouseButton::WheelDown) {
        wheelZoom(app->camera, *which);
        return;
    }
    const int glutModifiers = glutGetModifiers();
    const Modifiers modifiers{(glutModifiers & GLUT_ACTIVE_SHIFT) != 0, (glutModifiers & GLUT_ACTIVE_CTRL) != 0};
    const std::optional<SpaceHit> hit = pickAt(x, y);
    app->drag = dragForPress(*which, modifiers, hit && hit->hit.body.kind == BodyKind::Dynamic);
    logPick(hit, x, y);
    if (app->drag == Drag::Grab) {
        app->simulation->grab(hit->hit.body.index, hit->hit.point, mouseRay(x, y).direction,
                              *which == MouseButton::Right, hit->space);
        if (app->simulation->clock().paused()) notify("paused: Space resumes (or N steps), then the push acts");
    }
    describePointer(hit);
}

void onMotion(int x, int y) {
    const Real dx = Real(x - app->mouseX);
    const Real dy = Real(y - app->mouseY);
    app->mouseX = x;
    app->mouseY = y;
    if (app->drag == Drag::Grab) app->simulation->aimGrab(mouseRay(x, y).direction);
    else dragCamera(app->camera, app->drag, dx, dy, app->height);
}

void onPassiveMotion(int x, int y) {
    app->mouseX = x;
    app->mouseY = y;
    app->pointerInside = true;
    describePointer(pickAt(x, y));
}

void onEntry(int state) {
    app->pointerInside = state == GLUT_ENTERED;
    if (!app->pointerInside) describePointer(std::nullopt);  // a held body stays outlined
}

// ---- Screenshot mode ------------------------------------------------------

void onScreenshotDisplay() {
    if (app->screenshotPath.empty()) return;  // already taken; freeglut may ask again before leaving
    const int width = glutGet(GLUT_WINDOW_WIDTH);
    const int height = glutGet(GLUT_WINDOW_HEIGHT);
    if (width != app->width || height != app->height) {
        std::fprintf(stderr,
                     "stepwise view: the window is %dx%d, not the %dx%d asked for (a smaller screen?); "
                     "try a smaller --size or a bigger virtual screen: xvfb-run -a -s '-screen 0 1920x1080x24'\n",
                     width, height, app->width, app->height);
        app->exitCode = kExitUsageError;
    } else {
        try {
            writeFrame(app->screenshotPath, 0);
            const Simulation& sim = *app->simulation;
            if (const Spaces* spaces = sim.spaces()) {
                std::printf("Screenshot of %s at t = %.6g s on the spaces' clock (%zu spaces), %dx%d, written to %s\n",
                            sim.scenePath().c_str(), double(spaces->clock()), spaces->all().size(), width, height,
                            app->screenshotPath.c_str());
            } else {
                std::printf("Screenshot of %s at t = %.6g s (step %llu), %dx%d, written to %s\n",
                            sim.scenePath().c_str(), double(sim.world().time()),
                            static_cast<unsigned long long>(sim.world().stepCount()), width, height,
                            app->screenshotPath.c_str());
            }
            if (!app->dumpStatePath.empty()) {
                app->simulation->dumpState(app->dumpStatePath);
                std::printf("State written to %s\n", app->dumpStatePath.c_str());
            }
        } catch (const std::runtime_error& e) {
            std::fprintf(stderr, "stepwise view: %s\n", e.what());
            app->exitCode = kExitUsageError;
        }
    }
    app->screenshotPath.clear();
    glutLeaveMainLoop();
}

/// freeglut's fatal errors. freeglut expects this handler not to return (it
/// carries on, and crashes, if it does), so it ends the program.
[[noreturn]] void onGlutError(const char* format, va_list args) {
    std::fprintf(stderr, "stepwise view: freeglut: ");
    std::vfprintf(stderr, format, args);
    std::fprintf(stderr, "\n");
    std::exit(kExitUsageError);
}

void onGlutWarning(const char* format, va_list args) {
    std::fprintf(stderr, "stepwise view: freeglut warning: ");
    std::vfprintf(stderr, format, args);
    std::fprintf(stderr, "\n");
}

/// Creates the GLUT window (the display has been checked already).
void openWindow(const char* title) {
    int argc = 1;
    char name[] = "stepwise";
    char* argv[] = {name, nullptr};
    glutInitErrorFunc(onGlutError);
    glutInitWarningFunc(onGlutWarning);
    glutInit(&argc, argv);  // our own arguments are not GLUT's: it sees only the program name
    glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(app->width, app->height);
    glutCreateWindow(title);
}

/// In a sanitizer build, keeps the OpenGL driver libraries loaded until the process ends.
///
/// When the main loop ends, freeglut closes the display and Mesa unloads its
/// driver (e.g. swrast_dri.so); LeakSanitizer looks only at exit, by which
/// time the driver's own leftovers are attributed to an "<unknown module>"
/// that no suppression can name. Re-opening the loaded drivers with
/// RTLD_NODELETE keeps them mapped, so the report names them and
/// src/viewer/lsan_suppressions.txt (used by the viewer test) can too. Leaks
/// in Stepwise's own code are reported as always.
void keepDriversLoadedForLeakReports() {
#if defined(__SANITIZE_ADDRESS__)
    std::vector<std::string> drivers;
    dl_iterate_phdr(
        [](dl_phdr_info* info, std::size_t, void* list) {
            const std::string name = info->dlpi_name ? info->dlpi_name : "";
            if (name.find("_dri.so") != std::string::npos || name.find("libgallium") != std::string::npos) {
                static_cast<std::vector<std::string>*>(list)->push_back(name);
            }
            return 0;
        },
        &drivers);
    for (const std::string& name : drivers) dlopen(name.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
#endif
}

}  // namespace

int runViewer(const ViewOptions& options) {
    App state;
    state.width = options.width;
    state.height = options.height;
    try {
        state.simulation = std::make_unique<Simulation>(options.scenePath);
    } catch (const ConfigError& error) {
        for (const ConfigDiagnostic& d : error.diagnostics()) std::fprintf(stderr, "%s\n", d.message().c_str());
        std::fprintf(stderr, "stepwise: %zu error(s) in %s; nothing was loaded.\n", error.diagnostics().size(),
                     options.scenePath.c_str());
        return kExitUsageError;
    } catch (const std::invalid_argument& error) {
        std::fprintf(stderr, "stepwise: %s: %s\n", options.scenePath.c_str(), error.what());
        return kExitUsageError;
    }
    state.camera = frameScene(*state.simulation, state.width, state.height);

    auto check = std::make_unique<DisplayCheck>();
    if (const std::optional<std::string>& problem = check->problem()) {
        std::fprintf(stderr,
                     "stepwise view: cannot open a window: %s.\n"
                     "  On a desktop, run it from a terminal inside the graphical session; over SSH, use 'ssh -X'.\n"
                     "  Without a screen, draw into a virtual one (Debian package xvfb, which scripts/setup.sh "
                     "installs):\n"
                     "    xvfb-run -a stepwise view %s --screenshot out.png --at 2\n",
                     problem->c_str(), options.scenePath.c_str());
        return kExitUsageError;
    }

    app = &state;
    if (options.screenshotPath) {
        state.screenshot = true;
        state.screenshotPath = *options.screenshotPath;
        state.dumpStatePath = options.dumpStatePath.value_or("");
        try {
            state.simulation->stepTo(options.at);
        } catch (const SimulationError& error) {
            std::fprintf(stderr, "stepwise: simulation failed: %s\n", error.what());
            app = nullptr;
            return kExitSimulationError;
        }
        for (char key : options.keys) pressKey(static_cast<unsigned char>(key));
        if (options.stage && state.simulation->hasSpaces()) {
            std::fprintf(stderr, "stepwise view: --stage %zu: %s\n", *options.stage, kNoWalkthroughWithSpaces);
            app = nullptr;
            return kExitUsageError;
        }
        if (options.stage && !state.simulation->showStageRun(*options.stage - 1)) {
            std::fprintf(stderr, "stepwise view: --stage %zu: the step has %zu stage runs\n", *options.stage,
                         state.simulation->walkthrough().size());
            app = nullptr;
            return kExitUsageError;
        }
        openWindow("stepwise view (screenshot)");
        check.reset();  // freeglut has its own connection now
        glutDisplayFunc(onScreenshotDisplay);
    } else {
        if (options.logEventsPath) {
            try {
                state.log.open(*options.logEventsPath);
            } catch (const std::runtime_error& e) {
                std::fprintf(stderr, "stepwise view: %s\n", e.what());
                app = nullptr;
                return kExitUsageError;
            }
            state.simulation->setEventLog(&state.log);
        }
        openWindow(("stepwise view " + options.scenePath).c_str());
        check.reset();
        glutDisplayFunc(onDisplay);
        glutReshapeFunc(onReshape);
        glutKeyboardFunc(onKeyboard);
        glutMouseFunc(onMouse);
        glutMotionFunc(onMotion);
        glutPassiveMotionFunc(onPassiveMotion);
        glutEntryFunc(onEntry);
        glutTimerFunc(kFrameMilliseconds, onTimer, 0);
        state.lastFrame = Clock::now();
        notify("H: help");
    }
    keepDriversLoadedForLeakReports();
    glutMainLoop();  // when it returns, freeglut has closed the window and the display
    app = nullptr;
    return state.exitCode;
}

}  // namespace stepwise::viewer

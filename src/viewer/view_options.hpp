/// @file view_options.hpp
/// @brief What `stepwise view` is asked to do: the viewer's options, parsed by the command line (src/app/options.cpp).
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace stepwise::viewer {

/// @brief Options of `stepwise view` (the viewer in src/viewer/, built when STEPWISE_VIEWER is ON).
struct ViewOptions {
    std::string scenePath;                     ///< Scene file; the default scene when not given.
    std::optional<std::string> screenshotPath; ///< --screenshot PATH: draw one frame into this PNG and exit.
    double at = 0;                             ///< --at T: simulated time of the screenshot, s (≥ 0).
    int width = 960;                           ///< --size WxH: window width, pixels.
    int height = 600;                          ///< --size WxH: window height, pixels.
    std::optional<std::string> dumpStatePath;  ///< --dump-state PATH: the state drawn, as `run --csv` writes it.
    std::string keys;                          ///< --keys KEYS: keys pressed before the screenshot (e.g. "CV").
    std::optional<std::string> logEventsPath;  ///< --log-events PATH: one line per pick, push and release (window only).
    std::optional<std::size_t> stage;          ///< --stage K: show the state after the K-th stage run of the next step (S).
};

}  // namespace stepwise::viewer

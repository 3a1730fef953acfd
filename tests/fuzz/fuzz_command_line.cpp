// libFuzzer target: the `stepwise` command line's parsers of src/app/options.cpp (run, view, plot).
//
// The input is a command line: its arguments separated by NUL bytes, the first one the command.
// A bad command line must end in a UsageError, whose message main() prints with exit code 2;
// any other exception, crash or undefined operation is a bug. Nothing is run: only parsed.
//   build/fuzz/tests/fuzz/fuzz_command_line -max_total_time=600 build/fuzz/corpus/cli tests/fuzz/seeds/cli
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "app/cli.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace stepwise::cli;
    std::vector<std::string> args(1);
    for (std::size_t i = 0; i < size; ++i) {
        if (data[i] == 0) args.emplace_back();
        else args.back() += static_cast<char>(data[i]);
    }
    const std::string command = args.front();
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    try {
        if (command == "run") parseRunOptions(rest, "default.scene");
        else if (command == "view") parseViewOptions(rest, "default.scene");
        else if (command == "plot") parsePlotOptions(rest, "default.scene");
    } catch (const UsageError&) {
        // refused with a message: what a bad command line should get
    }
    return 0;
}

// Shared by the chapter tests: bad input is a usage error that writes nothing.
#include <kit_catch.hpp>

#include "process.hpp"

namespace kit::test {

void expect_usage_errors(const std::string& binary, const std::vector<BadInput>& cases) {
  for (const BadInput& bad : cases) {
    TempDir out("bad-input");
    const auto target = out.path() / "figures";
    auto args = bad.args;
    args.insert(args.end(), {"--out", target.string()});
    const auto result = run_process(binary, args);
    std::string command;
    for (const auto& arg : bad.args) command += arg + " ";
    INFO(command << "-> exit " << result.exit_code << ": " << result.err);
    CHECK(result.exit_code == 2);
    CHECK_THAT(result.err, ContainsSubstring(bad.names));
    CHECK(result.out.empty());
    CHECK_FALSE(std::filesystem::exists(target));
  }
}

}  // namespace kit::test

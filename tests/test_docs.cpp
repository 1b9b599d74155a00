// The documents stay true (issue 30): every `build/slide` command that the README and the user guide (docs/) show
// names a subcommand and options the program accepts (its --help lists them), and every case, sweep, script and
// linked page they name exists.
#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <set>

#include "tests/cli_helpers.hpp"

namespace slide::testing {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> documents() {
  std::vector<fs::path> docs{source_dir() / "README.md"};
  for (const auto& e : fs::directory_iterator(source_dir() / "docs"))
    if (e.path().extension() == ".md") docs.push_back(e.path());
  return docs;
}

// Each `build/slide SUB ...` command: on a code line, or in an inline code span.
std::vector<std::string> slide_commands(const std::string& text) {
  std::vector<std::string> commands;
  const std::regex command(R"(build/slide ([a-z]+)([^`\n#]*))");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), command); it != std::sregex_iterator(); ++it)
    commands.push_back((*it)[1].str() + (*it)[2].str());
  return commands;
}

TEST(Docs, EveryCommandTheReadmeAndGuideShowIsAccepted) {
  std::map<std::string, std::string> help;  // subcommand -> its --help
  int checked = 0;
  for (const auto& doc : documents()) {
    for (const auto& command : slide_commands(read_file(doc))) {
      const std::string sub = command.substr(0, command.find(' '));
      if (!help.count(sub)) {
        const auto r = run_command(slide_binary() + " " + sub + " --help");
        EXPECT_EQ(r.exit_code, 0) << doc << ": build/slide " << sub << " is not a subcommand: " << r.output;
        help[sub] = r.output;
      }
      const std::regex option(R"((--[a-z][a-z-]*))");
      for (auto it = std::sregex_iterator(command.begin(), command.end(), option); it != std::sregex_iterator(); ++it) {
        EXPECT_NE(help[sub].find((*it)[1].str()), std::string::npos)
            << doc.filename() << ": build/slide " << command << ": " << (*it)[1] << " is not an option of " << sub;
        ++checked;
      }
    }
  }
  EXPECT_GE(help.size(), 5u);  // run, check, report, sweep, schema
  EXPECT_GE(checked, 10);
}

TEST(Docs, EveryCaseScriptAndPageTheyNameExists) {
  const std::regex named(R"(((?:cases|tools|docs|tests)/[A-Za-z0-9_./-]+\.(?:yaml|md|py|png|cpp|hpp|sh)|tools/(?:run|test|setup|bench)\b))");
  const std::regex link(R"(\]\(([^)#:]+)(?:#[^)]*)?\))");
  int checked = 0;
  for (const auto& doc : documents()) {
    const std::string text = read_file(doc);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), named); it != std::sregex_iterator(); ++it) {
      std::string path = (*it)[1].str();
      while (!path.empty() && (path.back() == '.' || path.back() == '/')) path.pop_back();
      if (path.find('*') != std::string::npos || path.find("<") != std::string::npos) continue;
      EXPECT_TRUE(fs::exists(source_dir() / path)) << doc.filename() << " names " << path << ", which does not exist";
      ++checked;
    }
    for (auto it = std::sregex_iterator(text.begin(), text.end(), link); it != std::sregex_iterator(); ++it) {
      const fs::path target = doc.parent_path() / (*it)[1].str();
      EXPECT_TRUE(fs::exists(target)) << doc.filename() << " links " << (*it)[1] << ", which does not exist";
      ++checked;
    }
  }
  EXPECT_GE(checked, 30);
}

}  // namespace
}  // namespace slide::testing

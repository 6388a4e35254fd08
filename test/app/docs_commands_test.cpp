// Every kiln command in the documentation runs: each line starting with `kiln ` in a ```sh
// block of README.md and docs/**/*.md, in order per file, in a fresh folder that holds the
// repository's scenes/ (a link) and out/, with the scene files the page writes out in ```pbrt
// blocks (named by the `NAME.pbrt` mentioned just before the block). Renders get --spp 1 added
// (the last --spp wins) so that the suite stays quick; kiln farm finds a stand-in sbatch, and
// its --status may exit 1 (parts missing, as documented). Commands quoted inline in the prose
// (`kiln convert IN.exr -o OUT.png`, `kiln --emission MODEL`) are synopses with placeholders:
// each must name a real subcommand and only options its --help lists. scripts/test.sh is what
// CI itself runs, scripts/demo.sh is run by test/install/demo_test.sh; other programs (ffmpeg)
// are not run.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app_test_util.h"

namespace kiln {
namespace {

namespace fs = std::filesystem;
using testing::Q;

struct Page {
    std::string file;
    std::vector<std::pair<std::string, std::string>> sceneFiles;  // name, text
    std::vector<std::string> commands;
};

Page ReadPage(const fs::path& file) {
    Page page{file.string(), {}, {}};
    std::istringstream in(testing::ReadAll(file.string()));
    std::string line, fence, block, before;
    bool inBlock = false;
    while (std::getline(in, line)) {
        if (!inBlock && line.rfind("```", 0) == 0) {
            inBlock = true;
            fence = line.substr(3);
            block.clear();
            continue;
        }
        if (inBlock && line.rfind("```", 0) == 0) {
            inBlock = false;
            std::smatch m;
            if (fence == "pbrt" && std::regex_search(before, m, std::regex("`([\\w.-]+\\.pbrt)`")))
                page.sceneFiles.emplace_back(m[1], block);
            before.clear();
            continue;
        }
        if (inBlock) {
            block += line + "\n";
            if (fence == "sh" && line.rfind("kiln ", 0) == 0)
                page.commands.push_back(line.substr(0, line.find("   #")));
        } else if (!line.empty()) {
            before = line;
        }
    }
    return page;
}

TEST(DocsCommands, EveryKilnCommandInTheDocumentationRuns) {
    const fs::path root(KILN_SOURCE_DIR);
    std::vector<fs::path> files = {root / "README.md"};
    for (const auto& e : fs::recursive_directory_iterator(root / "docs"))
        if (e.path().extension() == ".md") files.push_back(e.path());
    const std::string kiln = std::string(KILN_BINARY_DIR) + "/kiln";
    int run = 0;
    for (const fs::path& file : files) {
        Page page = ReadPage(file);
        if (page.commands.empty()) continue;
        SCOPED_TRACE(page.file);
        fs::path dir = fs::path(::testing::TempDir()) /
                       ("kiln_docs_" + std::to_string(getpid()) + "_" + file.stem().string());
        fs::remove_all(dir);
        fs::create_directories(dir / "out");
        fs::create_directories(dir / "bin");
        fs::create_directory_symlink(root / "scenes", dir / "scenes");
        std::ofstream(dir / "bin" / "sbatch") << "#!/bin/sh\necho \"Submitted batch job 4711\"\n";
        fs::permissions(dir / "bin" / "sbatch", fs::perms::owner_all);
        for (const auto& [name, text] : page.sceneFiles) std::ofstream(dir / name) << text;
        for (const std::string& command : page.commands) {
            std::istringstream words(command);
            std::string word, first;
            words >> word >> first;
            bool render = first.size() > 5 && first.substr(first.size() - 5) == ".pbrt";
            std::string args = command.substr(5);
            std::string shell = "cd " + Q(dir.string()) + " && PATH=" + Q((dir / "bin").string()) +
                                ":$PATH " + Q(kiln) + " " + args +
                                (render ? " --spp 1 --quiet" : "") + " > log.txt 2>&1";
            int status = std::system(shell.c_str());
            // kiln farm --status exits 1 while parts are missing (as documented)
            bool statusQuery = command.find(" --status") != std::string::npos;
            EXPECT_TRUE(WIFEXITED(status) &&
                        (WEXITSTATUS(status) == 0 || (statusQuery && WEXITSTATUS(status) == 1)))
                << command << "\n"
                << testing::ReadAll((dir / "log.txt").string());
            ++run;
        }
        fs::remove_all(dir);
    }
    EXPECT_GE(run, 3);  // README's example, the cluster and animation pages
}

// The help text of kiln or of one of its subcommands (standard output and error).
std::string HelpOf(const std::string& subcommand) {
    std::string shell = testing::ShellQuote(std::string(KILN_BINARY_DIR) + "/kiln") + " " +
                        subcommand + (subcommand.empty() ? "" : " ") + "--help 2>&1";
    std::string text;
    if (FILE* p = popen(shell.c_str(), "r")) {
        char buf[4096];
        size_t n;
        while ((n = fread(buf, 1, sizeof(buf), p)) > 0) text.append(buf, n);
        pclose(p);
    }
    return text;
}

TEST(DocsCommands, EveryInlineKilnCommandNamesRealOptions) {
    const fs::path root(KILN_SOURCE_DIR);
    std::vector<fs::path> files = {root / "README.md"};
    for (const auto& e : fs::recursive_directory_iterator(root / "docs"))
        if (e.path().extension() == ".md") files.push_back(e.path());
    const std::set<std::string> subcommands = {"convert", "info", "diff", "merge", "farm"};
    std::map<std::string, std::string> help;
    int checked = 0;
    const std::regex span("`(kiln [^`]*)`"), option("(^|[\\s\\[])(--[a-z][a-z0-9-]*)");
    for (const fs::path& file : files) {
        std::string text = testing::ReadAll(file.string());
        for (std::sregex_iterator m(text.begin(), text.end(), span), end; m != end; ++m) {
            std::string command = (*m)[1];
            std::istringstream words(command.substr(5));
            std::string first;
            words >> first;
            std::string sub = subcommands.count(first) ? first : "";
            if (!help.count(sub)) help[sub] = HelpOf(sub);
            ASSERT_NE(help[sub].find("usage"), std::string::npos) << "kiln " << sub << " --help";
            for (std::sregex_iterator o(command.begin(), command.end(), option); o != end; ++o) {
                std::string name = (*o)[2];
                EXPECT_NE(help[sub].find(name), std::string::npos)
                    << file.filename().string() << ": `" << command << "` names " << name
                    << ", which kiln " << sub << (sub.empty() ? "" : " ") << "--help does not list";
            }
            ++checked;
        }
    }
    EXPECT_GE(checked, 30);
}

}  // namespace
}  // namespace kiln

// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// armstudy replaces only what it wrote: a user's folder or file of a case's name, a foreign
// run-level file (index.html, summary.md, ...), a link out of the output folder and what it
// points to, a page armstudy did not write: each is refused (exit 2) or left alone, byte for
// byte. And what it prints to PDF runs no script and reads no file outside its folder.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "report/case_report.hpp"
#include "testing/cli.hpp"
#include "testing/files.hpp"
#include "testing/output_folder.hpp"

namespace {
namespace fs = std::filesystem;
using armstudy::testing::fresh_dir;
using armstudy::testing::quick_case;
using armstudy::testing::run_cli;
using armstudy::testing::slurp;
using armstudy::testing::snapshot;

// `command` through the shell, standard input closed; its output and error captured
armstudy::testing::CliRun shell_group(const std::string& command) {
  armstudy::testing::CliRun r{-1, ""};
  FILE* p = popen(("{ " + command + "; } 2>&1 </dev/null").c_str(), "r");
  char buf[4096];
  while (p && fgets(buf, sizeof buf, p)) r.output += buf;
  const int status = p ? pclose(p) : -1;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// a user's folder: files, a hidden one, a sub-folder
void user_folder(const fs::path& d) {
  fs::create_directories(d / "sub");
  std::ofstream(d / "main.cpp") << "int main() { return 0; }\n";
  std::ofstream(d / ".hidden") << "secret\n";
  std::ofstream(d / "sub/notes.txt") << "my notes\n";
}

void set_age(const fs::path& p, std::chrono::minutes age) {
  fs::last_write_time(p, fs::file_time_type::clock::now() - age);
}

TEST(ForeignOutput, AUserFolderOrFileOfTheCasesNameIsRefusedAndKeptByteForByte) {
  const fs::path d = fresh_dir("foreign_case_folder");
  const fs::path out = d / "out";
  user_folder(out / "mine");
  std::ofstream(out / "file-case") << "a user's file\n";
  fs::create_directories(d / "elsewhere");
  fs::create_symlink(d / "elsewhere", out / "link-case");
  for (const char* name : {"mine", "file-case", "link-case"}) {
    const auto before = snapshot(d);
    const fs::path c = quick_case(d, name);
    const auto with_case = snapshot(d);
    const auto r = run_cli("run --no-render --out " + out.string() + " " + c.string());
    EXPECT_EQ(r.exit_code, 2) << name << "\n" << r.output;
    EXPECT_NE(r.output.find((out / name).string() + ": "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("; expected no such entry, or the case folder of an earlier run"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("nothing was written"), std::string::npos) << r.output;
    EXPECT_TRUE(snapshot(d) == with_case) << name << ": the output folder changed\n" << r.output;
    fs::remove(c);
    EXPECT_TRUE(snapshot(d) == before);
  }
  // `run x.yaml --out .` with a case named src, from a project folder
  const fs::path project = d / "project";
  user_folder(project / "src");
  const fs::path c = quick_case(d, "src");
  const auto before = snapshot(project);
  const auto here = shell_group("cd " + project.string() + " && " + ARMSTUDY_BINARY +
                                " run --no-render --out . " + c.string());
  EXPECT_EQ(here.exit_code, 2) << here.output;
  EXPECT_NE(here.output.find("./src: a folder armstudy did not write"), std::string::npos)
      << here.output;
  EXPECT_TRUE(snapshot(project) == before) << "./src changed\n" << here.output;
  fs::remove_all(d);
}

// a case folder holds armstudy's results.json for that case: one from an earlier version
// (only schema_version and case.name known) is replaced; one of another case is not
TEST(ForeignOutput, OnlyAFolderWithArmstudysResultsJsonForTheCaseIsReplaced) {
  const fs::path d = fresh_dir("foreign_results_json");
  const fs::path out = d / "out";
  const fs::path c = quick_case(d, "owned");
  fs::create_directories(out / "owned");
  std::ofstream(out / "owned/results.json")
      << R"({"schema_version": 1, "case": {"name": "owned"}, "status": "solved"})";
  std::ofstream(out / "owned/old-frame.png") << "png";
  auto r = run_cli("run --no-render --out " + out.string() + " " + c.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_FALSE(fs::exists(out / "owned/old-frame.png")) << "the earlier report was replaced";
  EXPECT_EQ(nlohmann::json::parse(slurp(out / "owned/results.json"))["case"]["name"], "owned");

  const std::map<std::string, std::string> foreign = {
      {"other", R"({"schema_version": 2, "case": {"name": "someone-else"}})"},
      {"no-schema", R"({"case": {"name": "no-schema"}})"},
      {"not-json", "results: yes\n"},
  };
  for (const auto& [name, text] : foreign) {
    fs::create_directories(out / name);
    std::ofstream(out / name / "results.json") << text;
    std::ofstream(out / name / "data.csv") << "1,2,3\n";
    const auto before = snapshot(out / name);
    r = run_cli("run --no-render --out " + out.string() + " " + quick_case(d, name).string());
    EXPECT_EQ(r.exit_code, 2) << name << "\n" << r.output;
    EXPECT_NE(r.output.find("a folder armstudy did not write"), std::string::npos) << r.output;
    EXPECT_TRUE(snapshot(out / name) == before) << name;
  }
  fs::remove_all(d);
}

TEST(ForeignOutput, ForeignRunLevelFilesAreNotOverwritten) {
  const fs::path d = fresh_dir("foreign_run_level");
  const fs::path out = d / "out";
  const fs::path c = quick_case(d, "beside");
  for (const char* name :
       {"index.html", "summary.md", "junit.xml", "report.css", "placement_root_loci.svg"}) {
    fs::remove_all(out);
    fs::create_directories(out);
    const std::string mine = std::string("the user's own ") + name + "\n";
    std::ofstream(out / name) << mine;
    const auto r = run_cli("run --no-render --out " + out.string() + " " + c.string());
    EXPECT_EQ(r.exit_code, 2) << name << "\n" << r.output;
    EXPECT_NE(r.output.find((out / name).string() + ": a file armstudy did not write"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(slurp(out / name), mine) << name;
    EXPECT_FALSE(fs::exists(out / "beside")) << name << ": nothing is written";
  }
  // merge too: its summary.md, junit.xml and index.html
  fs::remove_all(out);
  ASSERT_EQ(run_cli("run --no-render --out " + out.string() + " " + c.string()).exit_code, 0);
  std::ofstream(out / "summary.md", std::ios::trunc) << "# my summary\n";
  const auto before = snapshot(out);
  const auto m = run_cli("merge " + out.string());
  EXPECT_EQ(m.exit_code, 2) << m.output;
  EXPECT_TRUE(snapshot(out) == before) << m.output;
  // armstudy's own run-level files are replaced as before
  fs::remove(out / "summary.md");
  EXPECT_EQ(run_cli("merge " + out.string()).exit_code, 0);
  EXPECT_EQ(run_cli("merge " + out.string()).exit_code, 0);
  EXPECT_EQ(run_cli("run --force --no-render --out " + out.string() + " " + c.string()).exit_code,
            0);
  fs::remove_all(d);
}

// the stale-scratch clean-up removes only what armstudy names itself directly in the output
// folder (and in its own case folders): never through a link, never in a user's folder
TEST(ForeignOutput, CleanUpNeverFollowsALinkOutOfTheOutputFolder) {
  const fs::path d = fresh_dir("cleanup_links");
  const fs::path out = d / "out", outside = d / "outside";
  // what a killed run leaves, as seen through a link: stale scratch folders (no lock, old)
  // and old-style part files, one holding a "report" the clean-up would move back
  fs::create_directories(outside / ".armstudy-host-1-0badc0de/old/linked-case");
  std::ofstream(outside / ".armstudy-host-1-0badc0de/old/linked-case/results.json") << "{}";
  fs::create_directories(outside / ".armstudy-host-2-0badc0de.removing");
  std::ofstream(outside / "video.part-1") << "downloading";
  std::ofstream(outside / "summary.md.part-12-3") << "a user's file of armstudy's pattern";
  std::ofstream(outside / "lock") << "";
  user_folder(out / "mine");
  fs::create_directories(out / "mine/.armstudy-host-3-0badc0de");
  std::ofstream(out / "mine/data.part-4-5") << "user data";
  std::ofstream(out / "movie.part-6-7") << "a user's download beside the cases";
  fs::create_symlink(outside, out / "elsewhere");
  fs::create_symlink(outside, out / ".armstudy-host-4-0badc0de");
  fs::create_symlink(outside / ".armstudy-host-1-0badc0de", out / ".armstudy-host-5-0badc0de");
  for (const auto& e : fs::recursive_directory_iterator(d))
    if (!e.is_symlink()) set_age(e.path(), std::chrono::minutes(30));
  const auto outside_before = snapshot(outside), mine_before = snapshot(out / "mine");
  const auto r =
      run_cli("run --no-render --out " + out.string() + " " + quick_case(d, "clean").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(snapshot(outside) == outside_before) << "changed through a link\n" << r.output;
  EXPECT_TRUE(snapshot(out / "mine") == mine_before) << "a user's folder changed\n" << r.output;
  for (const char* link : {"elsewhere", ".armstudy-host-4-0badc0de", ".armstudy-host-5-0badc0de"})
    EXPECT_TRUE(fs::is_symlink(out / link)) << link << " is gone\n" << r.output;
  EXPECT_TRUE(fs::exists(out / "movie.part-6-7")) << "a user's file of a part-file name\n"
                                                  << r.output;
  EXPECT_FALSE(fs::exists(out / "linked-case")) << "a report moved in through a link";
  fs::remove_all(d);
}

// --pdf prints the pages of this run's cases that armstudy wrote, no other
TEST(ForeignOutput, PdfPrintsOnlyPagesArmstudyWrote) {
  if (armstudy::report::find_chromium().empty()) GTEST_SKIP() << "no Chromium";
  const fs::path d = fresh_dir("pdf_foreign_pages");
  const fs::path out = d / "out";
  user_folder(out / "user-site");
  std::ofstream(out / "user-site/index.html") << "<html><body>user page</body></html>";
  const fs::path c = quick_case(d, "printed");
  ASSERT_EQ(run_cli("run --no-render --out " + out.string() + " " + c.string()).exit_code, 0);
  // a page changed after armstudy wrote it (its sha256 in results.json no longer matches)
  std::ofstream(out / "printed/index.html", std::ios::app) << "<!-- edited -->";
  const auto before = snapshot(out / "user-site");
  auto r = run_cli("run --pdf --no-render --out " + out.string() + " " + c.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  // the edited page no longer has the sha256 its results.json lists: the case is redone
  // (the skip check) and the page printed is the one armstudy wrote again, not the edit
  EXPECT_EQ(slurp(out / "printed/index.html").find("<!-- edited -->"), std::string::npos);
  EXPECT_EQ(slurp(out / "printed/report.pdf").substr(0, 4), "%PDF") << r.output;
  EXPECT_FALSE(fs::exists(out / "user-site/report.pdf")) << "a user's page was printed";
  EXPECT_TRUE(snapshot(out / "user-site") == before);
  r = run_cli("run --pdf --force --no-render --out " + out.string() + " " + c.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(slurp(out / "printed/report.pdf").substr(0, 4), "%PDF") << r.output;
  EXPECT_FALSE(fs::exists(out / "user-site/report.pdf"));
  fs::remove_all(d);
}

// the printer itself: a page with a script and a file:// iframe of a file outside its
// folder prints neither the script's output nor the file's text
TEST(ForeignOutput, PrintingRunsNoScriptAndReadsNothingOutsideThePagesFolder) {
  if (armstudy::report::find_chromium().empty() || std::system("command -v pdftotext >/dev/null"))
    GTEST_SKIP() << "no Chromium or pdftotext";
  const fs::path d = fresh_dir("pdf_confined");
  fs::create_directories(d / "page");
  std::ofstream(d / "secret.txt") << "TOKEN-OUTSIDE-THE-FOLDER\n";
  std::ofstream(d / "page/inside.txt") << "TEXT-INSIDE-THE-FOLDER\n";
  fs::create_symlink(d / "secret.txt", d / "page/link.txt");
  std::ofstream(d / "page/index.html") << "<!DOCTYPE html><html><body><p>VISIBLE-TEXT</p>"
                                          "<script>document.write('SCRIPT-OUTPUT')</script>"
                                          "<iframe src=\"file://" +
                                              (d / "secret.txt").string() +
                                              "\"></iframe>"
                                              "<iframe src=\"link.txt\"></iframe>"
                                              "<iframe src=\"inside.txt\"></iframe></body></html>";
  armstudy::report::print_pdf(d / "page/index.html", d / "page.pdf");
  const std::string text = shell_group("pdftotext " + (d / "page.pdf").string() + " -").output;
  EXPECT_NE(text.find("VISIBLE-TEXT"), std::string::npos) << text;
  EXPECT_NE(text.find("TEXT-INSIDE-THE-FOLDER"), std::string::npos) << text;
  EXPECT_EQ(text.find("SCRIPT-OUTPUT"), std::string::npos) << text;
  EXPECT_EQ(text.find("TOKEN-OUTSIDE-THE-FOLDER"), std::string::npos) << text;
  // the same through the batch printer (one browser, several tabs)
  const auto errors = armstudy::report::print_pdfs(
      {{d / "page/index.html", d / "a.pdf"}, {d / "page/index.html", d / "b.pdf"}}, 2);
  for (const char* pdf : {"a.pdf", "b.pdf"}) {
    const std::string t = shell_group("pdftotext " + (d / pdf).string() + " -").output;
    EXPECT_NE(t.find("VISIBLE-TEXT"), std::string::npos) << t;
    EXPECT_EQ(t.find("SCRIPT-OUTPUT"), std::string::npos) << t;
    EXPECT_EQ(t.find("TOKEN-OUTSIDE-THE-FOLDER"), std::string::npos) << t;
  }
  fs::remove_all(d);
}

}  // namespace

namespace {

// armstudy diff writes diff.md, diff.html, report.css and diff-frames/ in its --out: a
// user's file or folder of one of those names is refused (exit 2) and kept byte for byte,
// and a diff armstudy wrote there before is replaced
TEST(ForeignOutput, DiffNeverOverwritesAUsersFileOrFolderOfItsOutputNames) {
  const fs::path d = fresh_dir("foreign_diff_outputs");
  const fs::path c = quick_case(d, "compared");
  ASSERT_EQ(run_cli("run --no-render --out " + (d / "a").string() + " " + c.string()).exit_code, 0);
  ASSERT_EQ(run_cli("run --no-render --out " + (d / "b").string() + " " + c.string()).exit_code, 0);
  const std::string diff = "diff " + (d / "a").string() + " " + (d / "b").string() + " --out ";
  for (const char* name : {"diff.md", "diff.html", "report.css"}) {
    const fs::path out = d / ("out-" + std::string(name));
    fs::create_directories(out);
    std::ofstream(out / name) << "a user's " << name << "\n";
    const auto before = snapshot(out);
    const auto r = run_cli(diff + out.string());
    EXPECT_EQ(r.exit_code, 2) << name << "\n" << r.output;
    EXPECT_NE(r.output.find(name), std::string::npos) << r.output;
    EXPECT_TRUE(snapshot(out) == before) << name << " was touched";
  }
  const fs::path out = d / "out-frames";
  user_folder(out / "diff-frames");
  const auto before = snapshot(out);
  auto r = run_cli(diff + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(snapshot(out) == before) << "a user's diff-frames folder was touched";
  // armstudy's own diff is replaced by the next one
  const fs::path mine = d / "out-mine";
  ASSERT_EQ(run_cli(diff + mine.string()).exit_code, 0);
  r = run_cli(diff + mine.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(slurp(mine / "diff.md").rfind("# armstudy diff: ", 0), 0u);
  fs::remove_all(d);
}

}  // namespace

// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// One headless Chromium prints every page of a run (print_pdfs over the DevTools pipe); a
// browser that dies costs nothing but time: its pages are printed one browser each.

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "report/case_report.hpp"
#include "testing/files.hpp"

namespace armstudy::report {
namespace {
namespace fs = std::filesystem;

using armstudy::testing::slurp;

size_t lines(const fs::path& p) {
  std::ifstream in(p);
  size_t n = 0;
  for (std::string l; std::getline(in, l);) ++n;
  return n;
}

// a browser that logs every start to `log`, then runs `body`
fs::path wrapper(const fs::path& dir, const fs::path& log, const std::string& body) {
  const fs::path w = dir / "browser";
  std::ofstream(w) << "#!/bin/sh\necho start >> '" << log.string() << "'\n" << body << "\n";
  ::chmod(w.c_str(), 0755);
  return w;
}

std::vector<PdfJob> pages(const fs::path& d, int n) {
  std::vector<PdfJob> jobs;
  for (int k = 0; k < n; ++k) {
    const fs::path html = d / ("page" + std::to_string(k) + ".html");
    std::ofstream(html) << "<html><head><style>@page { size: A5; }</style></head><body><h1>page "
                        << k << "</h1><p>printed by one browser</p></body></html>";
    jobs.push_back({html, d / ("page" + std::to_string(k) + ".pdf")});
  }
  return jobs;
}

TEST(PdfBatch, OneBrowserPrintsEveryPage) {
  const std::string chromium = find_chromium();
  if (chromium.empty()) GTEST_SKIP() << "no Chromium on this machine";
  const fs::path d = armstudy::testing::fresh_dir("pdf_batch_one");
  const fs::path log = d / "starts.log";
  setenv("ARMSTUDY_CHROMIUM", wrapper(d, log, "exec '" + chromium + "' \"$@\"").c_str(), 1);
  std::vector<PdfJob> jobs = pages(d, 3);
  jobs.push_back({d / "missing.html", d / "missing.pdf"});
  const std::vector<std::string> errors = print_pdfs(jobs, 2);
  unsetenv("ARMSTUDY_CHROMIUM");
  ASSERT_EQ(errors.size(), 4u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(errors[k], "") << k;
    const std::string pdf = slurp(jobs[k].pdf);
    EXPECT_EQ(pdf.substr(0, 4), "%PDF") << k;
    EXPECT_GT(pdf.size(), 500u) << k;
  }
  EXPECT_NE(errors[3].find("no such file"), std::string::npos) << errors[3];
  EXPECT_FALSE(fs::exists(jobs[3].pdf));
  EXPECT_EQ(lines(log), 1u) << "one browser for all pages";
  for (const auto& e : fs::directory_iterator(d))
    EXPECT_EQ(e.path().string().find(".part"), std::string::npos) << e.path();
}

// a browser that dies at once on its first start (the one meant for all pages): every page
// is then printed through print_pdf, each by a browser of its own
TEST(PdfBatch, ABrowserThatDiesCostsOnlyABrowserPerPage) {
  const std::string chromium = find_chromium();
  if (chromium.empty()) GTEST_SKIP() << "no Chromium on this machine";
  const fs::path d = armstudy::testing::fresh_dir("pdf_batch_fallback");
  const fs::path log = d / "starts.log";
  setenv("ARMSTUDY_CHROMIUM",
         wrapper(d, log,
                 "[ \"$(wc -l < '" + log.string() + "')\" = 1 ] && exit 1\nexec '" + chromium +
                     "' \"$@\"")
             .c_str(),
         1);
  const std::vector<PdfJob> jobs = pages(d, 3);
  const std::vector<std::string> errors = print_pdfs(jobs, 2);
  unsetenv("ARMSTUDY_CHROMIUM");
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(errors[k], "") << k;
    EXPECT_EQ(slurp(jobs[k].pdf).substr(0, 4), "%PDF") << k;
  }
  EXPECT_EQ(lines(log), 4u) << "the browser for all pages, then one per page";
}

TEST(PdfBatch, MissingChromiumIsAClearError) {
  const fs::path d = armstudy::testing::fresh_dir("pdf_batch_none");
  setenv("ARMSTUDY_CHROMIUM", (d / "no-such-browser").c_str(), 1);
  EXPECT_THROW(print_pdfs(pages(d, 2), 2), PdfError);
  unsetenv("ARMSTUDY_CHROMIUM");
}

}  // namespace
}  // namespace armstudy::report

#include "report.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace conformance {
namespace {

std::string html(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
    case '&': out += "&amp;"; break;
    case '<': out += "&lt;"; break;
    case '>': out += "&gt;"; break;
    case '"': out += "&quot;"; break;
    default: out += c;
    }
  }
  return out;
}

std::string fixed(double v, int digits) {
  if (std::isinf(v)) return "inf";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string diff_cell(const DiffStats& d) {
  if (!d.comparable) return "<td colspan=3 class=na>n/a</td>";
  return "<td>" + fixed(d.bad_percent, 3) + "</td><td>" + std::to_string(d.max_diff) +
         "</td><td>" + fixed(d.psnr, 1) + "</td>";
}

std::string image_cell(const std::string& dir, const std::string& scene, const char* file,
                       const char* caption, const ImplResult* impl) {
  std::ostringstream out;
  out << "<figure>";
  if (std::filesystem::exists(std::filesystem::path(dir) / scene / file)) {
    out << "<a href=\"" << html(scene) << "/" << file << "\"><img src=\"" << html(scene) << "/"
        << file << "\" alt=\"" << caption << "\"></a>";
  } else {
    out << "<div class=noimg>no image</div>";
  }
  out << "<figcaption>" << caption;
  if (impl && impl->attempted) {
    if (impl->median_ms > 0.0) out << " &middot; " << fixed(impl->median_ms, 2) << " ms";
    if (!impl->ok) out << "<br><span class=bad>" << html(impl->message) << "</span>";
  }
  out << "</figcaption></figure>";
  return out.str();
}

} // namespace

std::string write_report(const std::string& out_dir, const std::vector<SceneRecord>& records,
                         const std::string& command_line) {
  int passed = 0;
  std::vector<double> ratios_llvm, ratios_soft;
  for (const SceneRecord& r : records) {
    passed += r.passed ? 1 : 0;
    ratios_llvm.push_back(r.ratio_llvmpipe());
    ratios_soft.push_back(r.ratio_softpipe());
  }
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>Pineda conformance</title>\n"
      << "<style>body{font-family:sans-serif;margin:1em}table{border-collapse:collapse}"
         "td,th{border:1px solid #ccc;padding:2px 6px;font-size:13px;text-align:right}"
         "td.l{text-align:left}.pass{color:#080;font-weight:bold}.fail{color:#c00;"
         "font-weight:bold}.bad{color:#c00}.na{color:#999;text-align:center}"
         "section{margin:1.5em 0;border-top:2px solid #888;padding-top:.5em}"
         "figure{display:inline-block;margin:0 8px 0 0;vertical-align:top;max-width:300px}"
         "figure img{width:256px;image-rendering:pixelated;border:1px solid #888}"
         "figcaption{font-size:12px}.noimg{width:256px;height:256px;background:#eee;"
         "text-align:center;line-height:256px;color:#999}.why{font-style:italic}</style>"
         "</head><body>\n";
  out << "<h1>Pineda conformance against Mesa OSMesa</h1>\n<p>" << passed << " of "
      << records.size() << " scenes pass against their oracle. Geometric mean time ratio Pineda / "
      << "llvmpipe: " << fixed(geometric_mean(ratios_llvm), 2) << ", Pineda / softpipe: "
      << fixed(geometric_mean(ratios_soft), 2) << ". A pixel is bad when a channel differs by "
      << "more than the tolerance; a scene passes when its bad pixels stay within its allowance. "
      << "Rows show every scene whose result is in this directory, each from its own run (see "
      << "its time).</p>\n<p>Last command: <code>" << html(command_line) << "</code></p>\n";

  out << "<p>bad % / max / PSNR: Pineda against the scene's oracle, llvmpipe unless the scene "
         "is marked * (softpipe).</p>\n";
  out << "<table><tr><th>scene</th><th>result</th><th>bad %</th><th>max</th><th>PSNR</th>"
         "<th>allow %</th><th>Pineda ms</th><th>&times; llvmpipe</th><th>bad % vs softpipe</th>"
         "<th>max</th><th>PSNR</th><th>&times; softpipe</th><th>llvmpipe vs softpipe bad %</th>"
         "<th>max</th><th>PSNR</th></tr>\n";
  for (const SceneRecord& r : records) {
    out << "<tr><td class=l><a href=\"#" << html(r.name) << "\">" << html(r.name)
        << "</a>" << (r.softpipe_oracle() ? " *" : "") << "</td><td class=\"l "
        << (r.passed ? "pass\">pass" : "fail\">FAIL") << "</td>" << diff_cell(r.vs_oracle())
        << "<td>" << fixed(r.allowance, 2) << "</td><td>"
        << (r.pineda.median_ms > 0 ? fixed(r.pineda.median_ms, 2) : "") << "</td><td>"
        << (r.ratio_llvmpipe() > 0 ? fixed(r.ratio_llvmpipe(), 2) : "") << "</td>"
        << diff_cell(r.vs_softpipe) << "<td>"
        << (r.ratio_softpipe() > 0 ? fixed(r.ratio_softpipe(), 2) : "") << "</td>"
        << diff_cell(r.llvmpipe_vs_softpipe) << "</tr>\n";
  }
  out << "</table>\n";

  for (const SceneRecord& r : records) {
    out << "<section id=\"" << html(r.name) << "\"><h2>" << html(r.name) << " <span class="
        << (r.passed ? "pass>pass" : "fail>FAIL") << "</span></h2>\n<p>"
        << html(r.description) << "</p>\n";
    if (!r.passed) out << "<p class=bad>" << html(r.verdict) << "</p>\n";
    out << "<p>Allowance " << fixed(r.allowance, 2) << "% bad pixels, tolerance "
        << r.tolerance << ".";
    if (!r.why.empty()) out << " <span class=why>Why: " << html(r.why) << "</span>";
    out << "<br>Pineda vs " << r.oracle << " (oracle): ";
    const DiffStats& vs = r.vs_oracle();
    if (vs.comparable)
      out << fixed(vs.bad_percent, 3) << "% bad (" << vs.bad_pixels << " px), max "
          << vs.max_diff << ", PSNR " << fixed(vs.psnr, 1) << " dB";
    else
      out << "n/a";
    if (r.llvmpipe_vs_softpipe.comparable)
      out << "; llvmpipe vs softpipe: " << fixed(r.llvmpipe_vs_softpipe.bad_percent, 3)
          << "% bad, max " << r.llvmpipe_vs_softpipe.max_diff;
    out << ". Run " << html(r.when) << ".</p>\n";
    out << image_cell(out_dir, r.name, "pineda.png", "Pineda", &r.pineda)
        << image_cell(out_dir, r.name, "llvmpipe.png",
                      r.softpipe_oracle() ? "llvmpipe" : "llvmpipe (oracle)", &r.llvmpipe)
        << image_cell(out_dir, r.name, "softpipe.png",
                      r.softpipe_oracle() ? "softpipe (oracle)" : "softpipe", &r.softpipe)
        << image_cell(out_dir, r.name, "diff.png",
                      r.softpipe_oracle()
                          ? "diff Pineda vs softpipe (red: bad, green: within tolerance)"
                          : "diff Pineda vs llvmpipe (red: bad, green: within tolerance)",
                      nullptr)
        << "</section>\n";
  }
  out << "</body></html>\n";

  const std::string final_path = out_dir + "/report.html";
  const std::string temp_path = final_path + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream file(temp_path, std::ios::binary);
    file << out.str();
    if (!file) return "cannot write " + temp_path;
  }
  if (std::rename(temp_path.c_str(), final_path.c_str()) != 0) {
    std::remove(temp_path.c_str());
    return "cannot rename " + temp_path + " to " + final_path;
  }
  return {};
}

} // namespace conformance

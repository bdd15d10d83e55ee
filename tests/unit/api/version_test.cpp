// The version claim (GL 2.1 §6.1.11): GL_VERSION names the highest version whose every command
// Pineda implements. The commands are read from the registry (gl.xml, the <feature> blocks
// GL_VERSION_1_0 .. the claimed version), so the check cannot drift from the list in
// src/api/entry_points.txt.
#include "api_fixture.h"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

// Commands of the "gl" API features numbered <= major.minor.
std::vector<std::string> registry_commands(int major, int minor) {
  std::ifstream in(PINEDA_GL_XML);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string xml = ss.str();
  std::vector<std::string> out;
  size_t at = 0;
  while ((at = xml.find("<feature api=\"gl\"", at)) != std::string::npos) {
    const size_t end = xml.find("</feature>", at);
    const size_t num = xml.find("number=\"", at);
    int fmaj = 0, fmin = 0;
    if (num == std::string::npos || end == std::string::npos ||
        std::sscanf(xml.c_str() + num + 8, "%d.%d", &fmaj, &fmin) != 2)
      break;
    if (fmaj < major || (fmaj == major && fmin <= minor)) {
      for (size_t c = xml.find("<command name=\"", at); c != std::string::npos && c < end;
           c = xml.find("<command name=\"", c + 1)) {
        const size_t b = c + 15;
        out.push_back(xml.substr(b, xml.find('"', b) - b));
      }
    }
    at = end;
  }
  return out;
}

using Version = GLTest;

TEST_F(Version, EveryCommandOfTheClaimedVersionIsExported) {
  const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  ASSERT_NE(version, nullptr);
  int major = 0, minor = 0;
  ASSERT_EQ(std::sscanf(version, "%d.%d", &major, &minor), 2) << version;
  EXPECT_EQ(major, 2);
  EXPECT_EQ(minor, 1);
  const std::vector<std::string> commands = registry_commands(major, minor);
  ASSERT_GT(commands.size(), 400u) << "could not read " << PINEDA_GL_XML;
  for (const std::string& name : commands)
    EXPECT_NE(OSMesaGetProcAddress(name.c_str()), nullptr) << name << " is not exported";
}

TEST_F(Version, ExtensionsStringIsWellFormed) {
  const std::string ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  std::istringstream words(ext);
  for (std::string w; words >> w;)
    EXPECT_EQ(w.rfind("GL_", 0), 0u) << w;
  EXPECT_NE(ext.find("GL_ARB_texture_env_combine"), std::string::npos);
}

} // namespace

// Checks of the generated API layer (tools/gen/gen_gl.py): the enum name table, the
// proc-address table and the dispatch tables it builds from gl.xml and entry_points.txt.
#include <GL/gl.h>

#include <gtest/gtest.h>

#include <cstring>
#include <string_view>
#include <thread>

#include "dispatch.h"

namespace {

TEST(GeneratedEnumNames, KnownValuesHaveTheirRegistryName) {
  ASSERT_NE(pineda::enum_name(GL_TRIANGLES), nullptr);
  EXPECT_STREQ(pineda::enum_name(GL_TRIANGLES), "GL_TRIANGLES");
  EXPECT_STREQ(pineda::enum_name(GL_TEXTURE_2D), "GL_TEXTURE_2D");
  EXPECT_STREQ(pineda::enum_name(GL_INVALID_ENUM), "GL_INVALID_ENUM");
  // GL_ARRAY_BUFFER_ARB has the same value: the core (GL 1.5) name wins.
  EXPECT_STREQ(pineda::enum_name(GL_ARRAY_BUFFER), "GL_ARRAY_BUFFER");
}

TEST(GeneratedEnumNames, UnknownValueHasNoName) {
  EXPECT_EQ(pineda::enum_name(0x7FFFFFF0u), nullptr);
  EXPECT_EQ(pineda::enum_name(0x12345u), nullptr);
}

TEST(GeneratedEnumNames, TableIsSortedByValueWithoutDuplicates) {
  const auto table = pineda::enum_name_table();
  ASSERT_FALSE(table.empty());
  for (std::size_t i = 1; i < table.size(); ++i) {
    EXPECT_LT(table[i - 1].value, table[i].value) << table[i].name;
  }
  for (const auto& entry : table) {
    EXPECT_EQ(pineda::enum_name(entry.value), entry.name);
  }
}

TEST(GeneratedProcTable, FindsImplementedCommands) {
  void* const vertex = pineda::lookup_gl_proc("glVertex3f");
  ASSERT_NE(vertex, nullptr);
  EXPECT_EQ(vertex, reinterpret_cast<void*>(&glVertex3f));
  EXPECT_EQ(pineda::lookup_gl_proc("glBegin"), reinterpret_cast<void*>(&glBegin));
}

TEST(GeneratedProcTable, UnknownNamesAreNull) {
  EXPECT_EQ(pineda::lookup_gl_proc("glNoSuchCommand"), nullptr);
  EXPECT_EQ(pineda::lookup_gl_proc(""), nullptr);
  EXPECT_EQ(pineda::lookup_gl_proc(nullptr), nullptr);
  // Lookups are exact: no prefix or case-insensitive matches.
  EXPECT_EQ(pineda::lookup_gl_proc("glVertex3"), nullptr);
  EXPECT_EQ(pineda::lookup_gl_proc("glvertex3f"), nullptr);
}

TEST(GeneratedProcTable, IsSortedAndEveryEntryIsFound) {
  const auto table = pineda::gl_proc_table();
  ASSERT_FALSE(table.empty());
  for (std::size_t i = 1; i < table.size(); ++i) {
    EXPECT_LT(std::strcmp(table[i - 1].name, table[i].name), 0) << table[i].name;
  }
  for (const auto& entry : table) {
    EXPECT_TRUE(std::string_view(entry.name).starts_with("gl")) << entry.name;
    EXPECT_NE(entry.address, nullptr) << entry.name;
    EXPECT_EQ(pineda::lookup_gl_proc(entry.name), entry.address) << entry.name;
  }
}

TEST(GeneratedDispatch, ExecTableCallsTheImplementation) {
  EXPECT_EQ(pineda::kExecDispatch.Vertex3f, &pineda::exec::Vertex3f);
  EXPECT_EQ(pineda::kExecDispatch.GetError, &pineda::exec::GetError);
}

TEST(GeneratedDispatch, NoopTableDoesNothingAndReturnsZero) {
  EXPECT_NE(pineda::kNoopDispatch.Vertex3f, nullptr);
  EXPECT_EQ(pineda::kNoopDispatch.GetError(), 0u);
  EXPECT_EQ(pineda::kNoopDispatch.GetString(GL_VENDOR), nullptr);
  EXPECT_EQ(pineda::kNoopDispatch.IsEnabled(GL_DEPTH_TEST), GL_FALSE);
  GLint value = 1234;
  pineda::kNoopDispatch.GetIntegerv(GL_VIEWPORT, &value);
  EXPECT_EQ(value, 1234);
}

TEST(GeneratedDispatch, NewThreadsStartWithTheNoopTable) {
  // A fresh thread has no current context whatever other tests did on theirs.
  const pineda::Dispatch* seen = nullptr;
  std::thread([&seen] { seen = pineda::t_dispatch; }).join();
  EXPECT_EQ(seen, &pineda::kNoopDispatch);
}

} // namespace

#include <gtest/gtest.h>

#include "cad/FormatSniff.h"

using namespace aniso::cad;

TEST(FormatSniff, ExtensionAnyCase) {
  EXPECT_EQ(formatFromExtension("a/b.STEP"), CadFormat::Step);
  EXPECT_EQ(formatFromExtension("x.stp"), CadFormat::Step);
  EXPECT_EQ(formatFromExtension("x.IgEs"), CadFormat::Iges);
  EXPECT_EQ(formatFromExtension("x.igs"), CadFormat::Iges);
  EXPECT_EQ(formatFromExtension("x.brp"), CadFormat::Brep);
  EXPECT_EQ(formatFromExtension("x.Brep"), CadFormat::Brep);
  EXPECT_FALSE(formatFromExtension("x.xyz"));
  EXPECT_FALSE(formatFromExtension("step"));
}

TEST(FormatSniff, Content) {
  EXPECT_EQ(formatFromContent("ISO-10303-21;\nHEADER;"), CadFormat::Step);
  EXPECT_EQ(formatFromContent("\xEF\xBB\xBF  ISO-10303-21;\n"), CadFormat::Step);
  EXPECT_EQ(formatFromContent("/* exported by X */\n/* two */ ISO-10303-21;\n"), CadFormat::Step);
  EXPECT_FALSE(formatFromContent("/* an unterminated comment ISO-10303-21;\n"));
  EXPECT_EQ(formatFromContent("DBRep_DrawableShape\n\nCASCADE Topology V1"), CadFormat::Brep);
  EXPECT_EQ(formatFromContent("CASCADE Topology V3, (c) Open Cascade\n"), CadFormat::Brep);
  std::string iges(72, ' ');
  iges += "S      1\n";
  EXPECT_EQ(formatFromContent(iges), CadFormat::Iges);
  EXPECT_FALSE(formatFromContent("hello world\n"));
  EXPECT_FALSE(formatFromContent("\x89PNG\r\n\x1a\n"));
  std::string notIges(72, 'x');
  notIges += "Sabc\n";
  EXPECT_FALSE(formatFromContent(notIges));
}

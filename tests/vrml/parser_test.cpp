#include "engine/vrml/vrml_parser.h"

#include <gtest/gtest.h>

#include "engine/vrml/gzip.h"
#include "engine/vrml/vrml_fields.h"
#include "engine/vrml/vrml_reader.h"

namespace pw::engine::vrml {
namespace {

Result<Document> parse(const std::string& body, Diagnostics* diagnostics = nullptr) {
  auto file = std::make_shared<SourceFile>();
  file->displayName = "t.wrl";
  return parseDocument("#VRML V2.0 utf8\n" + body, file, diagnostics);
}

// The error message of a parse that must fail.
std::string errorOf(const std::string& body) {
  auto doc = parse(body);
  EXPECT_FALSE(doc.ok()) << "parsed: " << body;
  return doc.ok() ? std::string() : doc.message();
}

TEST(VrmlParser, AllFieldTypesWithAndWithoutBrackets) {
  auto doc = parse(R"(
    Transform { translation 1 2 3 rotation 0 1 0 1.5 scale 2 2 2 }
    Switch { whichChoice 0x2 }
    Material { diffuseColor 1 0.5 0 transparency 0.25 }
    WorldInfo { title "T" info [ "a" "b", "c" ] }
    Coordinate { point [ 1 2 3, 4 5 6, ] }
    Coordinate { point 7 8 9 }
    IndexedFaceSet { coordIndex [ 0 1 2 -1 ] solid FALSE }
    TimeSensor { cycleInterval 2.5 loop TRUE }
    PixelTexture { image 2 1 3 0xFF0000 0x00FF00 }
    NavigationInfo { type "FLY" avatarSize [] }
    OrientationInterpolator { key [0 1] keyValue [0 1 0 0, 0 1 0 3.14] }
  )");
  ASSERT_TRUE(doc.ok()) << doc.message();
  const auto& r = doc->roots;
  ASSERT_EQ(r.size(), 11u);
  EXPECT_EQ(getVec3(*r[0], "translation"), glm::dvec3(1, 2, 3));
  EXPECT_EQ(getVec4(*r[0], "rotation"), glm::dvec4(0, 1, 0, 1.5));
  EXPECT_EQ(getInt(*r[1], "whichChoice"), 2);
  EXPECT_DOUBLE_EQ(getDouble(*r[2], "transparency"), 0.25);
  EXPECT_EQ(getStrings(*r[3], "info"), (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(getFloats(*r[4], "point").size(), 6u);
  EXPECT_EQ(getFloats(*r[5], "point"), (std::vector<float>{7, 8, 9}));
  EXPECT_EQ(getInts(*r[6], "coordIndex"), (std::vector<int32_t>{0, 1, 2, -1}));
  EXPECT_FALSE(getBool(*r[6], "solid"));
  EXPECT_TRUE(getBool(*r[6], "ccw"));  // default
  EXPECT_DOUBLE_EQ(getDouble(*r[7], "cycleInterval"), 2.5);
  EXPECT_EQ(getInts(*r[8], "image"), (std::vector<int32_t>{2, 1, 3, 0xFF0000, 0x00FF00}));
  EXPECT_EQ(getStrings(*r[9], "type"), (std::vector<std::string>{"FLY"}));
  EXPECT_TRUE(getFloats(*r[9], "avatarSize").empty());
  EXPECT_EQ(getFloats(*r[10], "keyValue").size(), 8u);
}

TEST(VrmlParser, DefUseSharesTheNode) {
  auto doc = parse("Group { children [ DEF B Shape { geometry Box {} } Transform { children USE B } ] }");
  ASSERT_TRUE(doc.ok()) << doc.message();
  const auto& kids = getNodes(*doc->roots[0], "children");
  ASSERT_EQ(kids.size(), 2u);
  EXPECT_EQ(kids[0].get(), getNodes(*kids[1], "children")[0].get());
  EXPECT_EQ(kids[0]->defName, "B");
}

TEST(VrmlParser, SyntaxErrorsGiveLineColumnAndWhatWasExpected) {
  EXPECT_EQ(errorOf("Transform {\n  translation 1 2 }"),
            "t.wrl:3:19: field 'translation' (SFVec3f) expects 3 numbers per value (got 2), found '}'");
  EXPECT_EQ(errorOf("Shape {\n geometry Box { }\n"), "t.wrl:4:1: expected '}' to close the Shape opened at t.wrl:2:1, found end of file");
  EXPECT_EQ(errorOf("Group { children [ Shape { } }"),
            "t.wrl:2:30: expected a node, USE or ']', found '}'");
  EXPECT_EQ(errorOf("Shape { geometry USE Nothing }"), "t.wrl:2:18: USE Nothing refers to no node: no DEF Nothing precedes it");
  EXPECT_EQ(errorOf("WorldInfo { title \"abc }\n"),
            "t.wrl:2:19: an unterminated string (its opening '\"' is never closed)");
  EXPECT_EQ(errorOf("Material { diffuseColor TRUE 0 0 }"),
            "t.wrl:2:25: field 'diffuseColor' (SFColor) expects a number, found 'TRUE'");
  EXPECT_EQ(errorOf("Switch { whichChoice 1.5 }"),
            "t.wrl:2:22: field 'whichChoice' (SFInt32) expects an integer, found the number 1.5");
  EXPECT_EQ(errorOf("Shape { geometry 12 }"),
            "t.wrl:2:18: expected a node, USE, NULL for field 'geometry' (SFNode), found the number 12");
  EXPECT_EQ(errorOf("}"), "t.wrl:2:1: expected a node, PROTO or ROUTE, found '}'");
  EXPECT_EQ(errorOf("Coordinate { point [ 1 2 3"),
            "t.wrl:2:27: expected ']' to close the list of field 'point' opened at 2:20, found end of file");
  EXPECT_EQ(errorOf("Transform { set_translation 1 2 3 }"),
            "t.wrl:2:13: set_translation is an eventIn of Transform and cannot be given a value (only 'IS' inside a PROTO)");
  EXPECT_EQ(errorOf("Material { transparency 1e39 }"),
            "t.wrl:2:25: the number 1e39 in field 'transparency' is outside the single-precision range");
}

TEST(VrmlParser, UseCannotReferToTheNodeBeingDefined) {
  // Registering DEF names only once a node is complete keeps the graph acyclic.
  EXPECT_NE(errorOf("DEF A Group { children USE A }").find("USE A refers to no node"), std::string::npos);
}

TEST(VrmlParser, HeaderIsChecked) {
  auto file = std::make_shared<SourceFile>();
  file->displayName = "h.wrl";
  auto v1 = parseDocument("#VRML V1.0 ascii\nSeparator {}", file, nullptr);
  ASSERT_FALSE(v1.ok());
  EXPECT_NE(v1.message().find("VRML 1.0 is not supported"), std::string::npos);
  auto empty = parseDocument("", file, nullptr);
  ASSERT_FALSE(empty.ok());
  EXPECT_EQ(empty.message(), "h.wrl: the file is empty; a VRML97 file starts with '#VRML V2.0 utf8'");
  auto other = parseDocument("Shape {}", file, nullptr);
  ASSERT_FALSE(other.ok());
  EXPECT_NE(other.message().find("not a VRML97 file"), std::string::npos);
  auto x3d = parseDocument("#X3D V3.0 utf8\n", file, nullptr);
  ASSERT_FALSE(x3d.ok());
  EXPECT_NE(x3d.message().find("X3D"), std::string::npos);
}

TEST(VrmlParser, UnknownNodesAndFieldsAreSkippedWithWarnings) {
  Diagnostics d;
  auto doc = parse(R"(
    DEF U FancyNode { children [ Shape { } ] nested { a [ 1 2 ] } }
    ImageTexture { url "x.png" alphaChannel "TEST" repeatS FALSE }
    Shape { geometry USE U }
  )", &d);
  ASSERT_TRUE(doc.ok()) << doc.message();
  ASSERT_EQ(doc->roots.size(), 2u);  // the unknown node is gone
  EXPECT_FALSE(getBool(*doc->roots[0], "repeatS"));  // parsing went on after the unknown field
  EXPECT_EQ(d.warningCount(), 2);
  EXPECT_NE(d.format().find("t.wrl:3:11: unknown node type FancyNode; skipped"), std::string::npos);
  EXPECT_NE(d.format().find("ImageTexture has no field alphaChannel"), std::string::npos);
}

TEST(VrmlParser, RoutesAndScriptsParseAndAreNoted) {
  Diagnostics d;
  auto doc = parse(R"(
    DEF T TimeSensor { loop TRUE }
    DEF S Script {
      url "javascript: function f(v) { }"
      field SFNode target NULL
      field MFFloat values [ 1 2 ]
      eventIn SFFloat set_fraction
      eventOut SFVec3f out
    }
    DEF P Transform { }
    ROUTE T.fraction_changed TO S.set_fraction
    ROUTE S.out TO P.set_translation
  )", &d);
  ASSERT_TRUE(doc.ok()) << doc.message();
  EXPECT_EQ(doc->roots.size(), 3u);
  EXPECT_NE(d.format().find("ROUTEs are ignored"), std::string::npos);
  EXPECT_EQ(d.warningCount(), 0);
}

TEST(VrmlParser, ProtoInterfaceAndIsChecks) {
  EXPECT_NE(errorOf("PROTO P [ field SFColor c 1 0 0 ] { Material { diffuseColor IS nothere } }")
                .find("PROTO P has no field or event named nothere"),
            std::string::npos);
  EXPECT_NE(errorOf("PROTO P [ field SFFloat c 1 ] { Material { diffuseColor IS c } }")
                .find("diffuseColor is SFColor but P.c is SFFloat"),
            std::string::npos);
  EXPECT_NE(errorOf("Material { diffuseColor IS c }").find("IS is only allowed inside a PROTO body"),
            std::string::npos);
  EXPECT_NE(errorOf("PROTO P [ ] { }").find("has no node"), std::string::npos);
  // DEF names inside a PROTO body are not visible outside it.
  EXPECT_NE(errorOf("PROTO P [ ] { DEF Inner Group { } } Transform { children USE Inner }").find("USE Inner"),
            std::string::npos);
}

TEST(VrmlParser, HundredThousandNestedGroupsParseWithoutRecursion) {
  constexpr int kDepth = 100000;
  std::string text;
  text.reserve(kDepth * 24);
  for (int i = 0; i < kDepth; ++i) text += "Group { children [\n";
  text += "Shape { geometry Box { } }\n";
  for (int i = 0; i < kDepth; ++i) text += "] }\n";
  Diagnostics d;
  auto scene = engine::readVrmlString("#VRML V2.0 utf8\n" + text, ".", &d);
  ASSERT_TRUE(scene.ok()) << scene.message();
  EXPECT_EQ(scene->shapes.size(), 1u);
}

TEST(VrmlParser, UnclosedDeepNestingReportsTheInnermostOpening) {
  std::string text = "#VRML V2.0 utf8\n";
  for (int i = 0; i < 50000; ++i) text += "Group { children [\n";
  auto scene = engine::readVrmlString(text, ".", nullptr, "deep.wrl");
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.message(), "deep.wrl:50002:1: expected ']' to close the list opened at deep.wrl:50001:18, found end of file");
}

TEST(VrmlParser, HugeArraysParse) {
  constexpr int kPoints = 1000000;
  std::string text = "#VRML V2.0 utf8\nShape { geometry PointSet { coord Coordinate { point [\n";
  text.reserve(kPoints * 12);
  for (int i = 0; i < kPoints; ++i) text += std::to_string(i % 1000) + " 1 2,\n";
  text += "] } } }\n";
  auto scene = engine::readVrmlString(text, ".", nullptr);
  ASSERT_TRUE(scene.ok()) << scene.message();
  ASSERT_EQ(scene->shapes.size(), 1u);
  EXPECT_EQ(scene->shapes[0].mesh->positions.size(), static_cast<size_t>(kPoints));
  EXPECT_EQ(scene->shapes[0].mesh->positions[999], glm::vec3(999, 1, 2));
}

TEST(VrmlParser, DeclaredHugeImageWithoutPixelsIsAnErrorNotAnAllocation) {
  auto scene = engine::readVrmlString("#VRML V2.0 utf8\nPixelTexture { image 60000 60000 4 1 2 3 }", ".", nullptr, "p.wrl");
  ASSERT_FALSE(scene.ok());
  EXPECT_NE(scene.message().find("larger than the 64 megapixels"), std::string::npos);
  auto truncated = engine::readVrmlString("#VRML V2.0 utf8\nPixelTexture { image 4 4 1 1 2 3 }", ".", nullptr, "p.wrl");
  ASSERT_FALSE(truncated.ok());
  EXPECT_EQ(truncated.message(), "p.wrl:2:34: field 'image' (SFImage) expects an integer, found '}'");
}

TEST(VrmlParser, GzipTruncatedAndCorruptStreamsAreErrors) {
  auto packed = gzipCompress("#VRML V2.0 utf8\nShape { geometry Sphere { } }\n");
  ASSERT_TRUE(packed.ok());
  auto whole = engine::readVrmlString(*packed, ".", nullptr, "z.wrl");
  ASSERT_TRUE(whole.ok()) << whole.message();
  EXPECT_EQ(whole->shapes.size(), 1u);
  auto truncated = engine::readVrmlString(packed->substr(0, packed->size() / 2), ".", nullptr, "z.wrl");
  ASSERT_FALSE(truncated.ok());
  EXPECT_EQ(truncated.message(), "z.wrl: the gzip stream is truncated (the file ends before the compressed data does)");
  std::string corrupt = *packed;
  for (size_t i = 12; i < corrupt.size() - 8; i += 3) corrupt[i] = static_cast<char>(corrupt[i] ^ 0x5a);
  auto bad = engine::readVrmlString(corrupt, ".", nullptr, "z.wrl");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message().find("z.wrl: "), std::string::npos);
  auto magicOnly = engine::readVrmlString(std::string("\x1f\x8b", 2), ".", nullptr, "z.wrl");
  ASSERT_FALSE(magicOnly.ok());
}

}  // namespace
}  // namespace pw::engine::vrml

#include "engine/vrml/vrml_geometry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/vrml/polygon_mesh.h"
#include "engine/vrml/vrml_reader.h"

namespace pw::engine::vrml {
namespace {

glm::vec3 faceNormal(const Mesh& m, size_t t) {
  const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]], c = m.positions[m.indices[t + 2]];
  return glm::cross(b - a, c - a);
}

// Every non-degenerate triangle winds counter-clockwise seen from the side its vertex
// normals point to.
void expectOutwardWinding(const Mesh& m) {
  ASSERT_EQ(m.indices.size() % 3, 0u);
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    const glm::vec3 n = faceNormal(m, t);
    if (glm::length(n) < 1e-6f) continue;
    const glm::vec3 vn = m.normals[m.indices[t]] + m.normals[m.indices[t + 1]] + m.normals[m.indices[t + 2]];
    EXPECT_GT(glm::dot(n, vn), 0.0f) << "triangle " << t / 3;
  }
}

// For a convex solid around `inside`: every non-degenerate triangle faces away from
// it, by its winding and by its vertex normals, so an inside-out solid (winding and
// normals flipped together, which expectOutwardWinding cannot see) fails.
void expectFacesPointAwayFrom(const Mesh& m, const glm::vec3& inside) {
  ASSERT_EQ(m.indices.size() % 3, 0u);
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    const glm::vec3 n = faceNormal(m, t);
    if (glm::length(n) < 1e-6f) continue;
    const glm::vec3 centroid =
        (m.positions[m.indices[t]] + m.positions[m.indices[t + 1]] + m.positions[m.indices[t + 2]]) / 3.0f;
    EXPECT_GT(glm::dot(n, centroid - inside), 0.0f) << "triangle " << t / 3 << " winds inwards";
    for (size_t k = 0; k < 3; ++k) {
      EXPECT_GT(glm::dot(m.normals[m.indices[t + k]], centroid - inside), 0.0f)
          << "triangle " << t / 3 << " vertex " << k << ": normal points inwards";
    }
  }
}

Scene read(const std::string& body, Diagnostics* d = nullptr) {
  auto scene = engine::readVrmlString("#VRML V2.0 utf8\n" + body, PW_TEST_DATA_DIR "/vrml", d);
  EXPECT_TRUE(scene.ok()) << scene.message();
  return scene.ok() ? std::move(*scene) : Scene{};
}

TEST(VrmlPrimitives, BoxFacesPointOutAndShowTheImageUpright) {
  const Mesh box = makeBox({2, 4, 6}, true);
  EXPECT_EQ(box.positions.size(), 24u);
  EXPECT_EQ(box.indices.size(), 36u);
  expectOutwardWinding(box);
  expectFacesPointAwayFrom(box, glm::vec3(0.0f));
  EXPECT_EQ(localBounds(box).max, glm::vec3(1, 2, 3));
  // Front face: bottom-left corner at texture (0, 0); top face: its -Z edge is the image top.
  for (size_t i = 0; i < box.positions.size(); ++i) {
    const glm::vec3 p = box.positions[i], n = box.normals[i];
    if (n == glm::vec3(0, 0, 1) && p.x < 0 && p.y < 0) {
      EXPECT_EQ(box.texCoords[i], glm::vec2(0, 0));
    }
    if (n == glm::vec3(0, 1, 0) && p.x < 0 && p.z < 0) {
      EXPECT_EQ(box.texCoords[i], glm::vec2(0, 1));
    }
    if (n == glm::vec3(0, 0, -1) && p.x > 0 && p.y < 0) {
      EXPECT_EQ(box.texCoords[i], glm::vec2(0, 0));
    }
  }
}

TEST(VrmlPrimitives, SphereWrapsTheTextureFromTheBack) {
  const Mesh s = makeSphere(2.0f, true);
  expectOutwardWinding(s);
  expectFacesPointAwayFrom(s, glm::vec3(0.0f));
  for (size_t i = 0; i < s.positions.size(); ++i) {
    EXPECT_NEAR(glm::length(s.positions[i]), 2.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(s.normals[i], s.positions[i] / 2.0f), 1.0f, 1e-5f);
    const glm::vec2 t = s.texCoords[i];
    // s = 0.5 faces +Z (the default viewer), s = 0.25 faces -X; t = 1 at the top.
    if (std::fabs(t.y - 0.5f) < 1e-6f && std::fabs(t.x - 0.5f) < 1e-6f) {
      EXPECT_NEAR(s.positions[i].z, 2.0f, 1e-5f);
    }
    if (std::fabs(t.y - 0.5f) < 1e-6f && std::fabs(t.x - 0.25f) < 1e-6f) {
      EXPECT_NEAR(s.positions[i].x, -2.0f, 1e-5f);
    }
    if (t.y == 1.0f) {
      EXPECT_NEAR(s.positions[i].y, 2.0f, 1e-5f);
    }
  }
}

TEST(VrmlPrimitives, CylinderAndConePartsCanBeLeftOut) {
  const Mesh all = makeCylinder(1, 2, true, true, true, false, 16);
  const Mesh sideOnly = makeCylinder(1, 2, true, false, false, false, 16);
  expectOutwardWinding(all);
  expectFacesPointAwayFrom(all, glm::vec3(0.0f));
  expectFacesPointAwayFrom(sideOnly, glm::vec3(0.0f));
  EXPECT_EQ(all.indices.size(), 3u * (32 + 16 + 16));
  EXPECT_EQ(sideOnly.indices.size(), 3u * 32);
  const Mesh cone = makeCone(1, 2, true, true, false, 16);
  expectOutwardWinding(cone);
  expectFacesPointAwayFrom(cone, glm::vec3(0.0f));
  EXPECT_EQ(localBounds(cone).max.y, 1.0f);
  EXPECT_EQ(makeCone(1, 2, false, true, false, 16).indices.size(), 3u * 16);
  // The side normal of a cone with height 2 and radius 1 leans up by atan(1/2).
  EXPECT_NEAR(cone.normals[0].y, 1.0f / std::sqrt(5.0f), 1e-5f);
}

double absoluteArea(const Mesh& m) {
  double area = 0;
  for (size_t t = 0; t < m.indices.size(); t += 3) area += 0.5 * glm::length(faceNormal(m, t));
  return area;
}

TEST(VrmlFaceSet, NonConvexPolygonIsEarClipped) {
  auto scene = engine::readVrml(PW_TEST_DATA_DIR "/vrml/nonconvex.wrl", nullptr);
  ASSERT_TRUE(scene.ok()) << scene.message();
  const Mesh& m = *scene->shapes.at(0).mesh;
  EXPECT_EQ(m.indices.size(), 12u);
  EXPECT_NEAR(absoluteArea(m), 3.0, 1e-6);
  for (size_t t = 0; t < m.indices.size(); t += 3) EXPECT_GT(faceNormal(m, t).z, 0.0f);
}

TEST(VrmlFaceSet, ConvexFlagFansTheSamePolygon) {
  // The control for the test above: fanned, the L folds over itself.
  Scene scene = read(R"(Shape { geometry IndexedFaceSet {
    coord Coordinate { point [ 2 1 0, 1 1 0, 1 2 0, 0 2 0, 0 0 0, 2 0 0 ] } coordIndex [ 0 1 2 3 4 5 ] } })");
  EXPECT_GT(absoluteArea(*scene.shapes.at(0).mesh), 3.5);
}

TEST(VrmlFaceSet, TriangulatesAConcaveStar) {
  std::vector<glm::vec3> star;
  for (int i = 0; i < 10; ++i) {
    const float a = static_cast<float>(i) * 0.6283185f, r = i % 2 ? 0.4f : 1.0f;
    star.push_back({r * std::cos(a), r * std::sin(a), 0});
  }
  std::vector<uint32_t> tris;
  triangulatePolygon(star, tris);
  ASSERT_EQ(tris.size(), 24u);
  double area = 0;
  for (size_t t = 0; t < tris.size(); t += 3) {
    const glm::vec3 n = glm::cross(star[tris[t + 1]] - star[tris[t]], star[tris[t + 2]] - star[tris[t]]);
    EXPECT_GT(n.z, 0.0f);
    area += 0.5 * n.z;
  }
  // Ten triangles (centre, outer, inner) of the star: 10 * 0.5 * 1 * 0.4 * sin(36 deg).
  EXPECT_NEAR(area, 10 * 0.5 * 0.4 * std::sin(0.6283185), 1e-5);
}

const char* kCube = R"(Shape { geometry IndexedFaceSet {
  creaseAngle %s
  coord Coordinate { point [ -1 -1 1, 1 -1 1, 1 1 1, -1 1 1, -1 -1 -1, 1 -1 -1, 1 1 -1, -1 1 -1 ] }
  coordIndex [ 0 1 2 3 -1, 5 4 7 6 -1, 1 5 6 2 -1, 4 0 3 7 -1, 3 2 6 7 -1, 4 5 1 0 -1 ] } })";

std::string cube(const char* crease) {
  char buffer[1024];
  std::snprintf(buffer, sizeof buffer, kCube, crease);
  return buffer;
}

TEST(VrmlFaceSet, CreaseAngleSplitsOrSmoothsNormals) {
  const Scene flat = read(cube("0"));
  const Mesh& f = *flat.shapes.at(0).mesh;
  EXPECT_EQ(f.positions.size(), 24u);
  expectOutwardWinding(f);
  expectFacesPointAwayFrom(f, glm::vec3(0.0f));
  for (const glm::vec3& n : f.normals) EXPECT_NEAR(std::fabs(n.x) + std::fabs(n.y) + std::fabs(n.z), 1.0f, 1e-6f);
  const Scene smooth = read(cube("1.6"));  // above 90 degrees: every cube edge is smoothed
  const Mesh& s = *smooth.shapes.at(0).mesh;
  EXPECT_EQ(s.positions.size(), 8u);
  for (size_t i = 0; i < s.positions.size(); ++i) {
    EXPECT_NEAR(glm::dot(s.normals[i], glm::normalize(s.positions[i])), 1.0f, 1e-5f);
  }
  const Scene justBelow = read(cube("1.5"));  // below 90 degrees: still flat
  EXPECT_EQ(justBelow.shapes.at(0).mesh->positions.size(), 24u);
}

TEST(VrmlFaceSet, ManyFacesAroundOnePointSmoothWithinEachCrease) {
  // A "tent" of 2000 triangles around the origin: half slope one way, half the other,
  // 60 degrees apart. With creaseAngle 0.5 each side is smooth on its own: the centre
  // gets exactly two normals, one per side (the clustered path for >256 faces).
  constexpr int kFaces = 2000;
  std::string points = "0 0 0", index;
  for (int i = 0; i <= kFaces; ++i) {
    const double a = 3.14159265358979 * 2 * i / kFaces;
    const double x = std::cos(a), y = std::sin(a);
    points += ", " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(x > 0 ? x * 0.577 : -x * 0.577);
  }
  for (int i = 0; i < kFaces; ++i) index += "0 " + std::to_string(i + 1) + " " + std::to_string(i + 2) + " -1 ";
  const Scene s = read("Shape { geometry IndexedFaceSet { creaseAngle 0.5 coord Coordinate { point [ " + points +
                       " ] } coordIndex [ " + index + " ] } }");
  const Mesh& m = *s.shapes.at(0).mesh;
  std::vector<glm::vec3> centre;
  for (size_t i = 0; i < m.positions.size(); ++i) {
    if (m.positions[i] == glm::vec3(0.0f)) centre.push_back(m.normals[i]);
  }
  ASSERT_EQ(centre.size(), 2u);
  for (const glm::vec3& n : centre) {
    EXPECT_NEAR(std::fabs(n.x), 0.5f, 0.02f);  // each side's own slope, (-+0.5, 0, 0.866)
    EXPECT_NEAR(n.z, 0.866f, 0.02f);
  }
}

TEST(VrmlFaceSet, ClockwiseFacesAreTurnedAround) {
  const Scene s = read(R"(Shape { geometry IndexedFaceSet { ccw FALSE
    coord Coordinate { point [ 0 0 0, 1 0 0, 0 1 0 ] } coordIndex [ 0 1 2 ] } })");
  const Mesh& m = *s.shapes.at(0).mesh;
  // Listed counter-clockwise seen from +Z, but ccw FALSE says the front is -Z.
  EXPECT_LT(faceNormal(m, 0).z, 0.0f);
  EXPECT_NEAR(m.normals[0].z, -1.0f, 1e-6f);
}

TEST(VrmlFaceSet, PerFaceColoursAndNormalsWithIndices) {
  const Scene s = read(R"(Shape { geometry IndexedFaceSet {
    colorPerVertex FALSE normalPerVertex FALSE
    coord Coordinate { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0, 2 0 0 ] }
    color Color { color [ 1 0 0, 0 0 1 ] }
    colorIndex [ 1 0 ]
    normal Normal { vector [ 0 0 1, 0 0 2 ] }
    normalIndex [ 0 1 ]
    coordIndex [ 0 1 2 3 -1, 1 4 2 -1 ] } })");
  const Mesh& m = *s.shapes.at(0).mesh;
  ASSERT_EQ(m.indices.size(), 9u);
  EXPECT_EQ(m.colors[m.indices[0]], glm::vec4(0, 0, 1, 1));  // face 0 takes colorIndex[0] = 1
  EXPECT_EQ(m.colors[m.indices[6]], glm::vec4(1, 0, 0, 1));
  EXPECT_EQ(m.normals[m.indices[6]], glm::vec3(0, 0, 1));    // normalised
  // Points 1 and 2 belong to both faces with different colours: split vertices.
  EXPECT_EQ(m.positions.size(), 7u);
}

TEST(VrmlFaceSet, DefaultTextureCoordinatesFollowTheBoundingBox) {
  const Scene s = read(R"(Shape { appearance Appearance { texture ImageTexture { url "sub/checker.png" } }
    geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, 4 0 0, 4 2 0, 0 2 0 ] } coordIndex [ 0 1 2 3 ] } })");
  const Mesh& m = *s.shapes.at(0).mesh;
  ASSERT_EQ(m.texCoords.size(), 4u);
  EXPECT_EQ(m.texCoords[2], glm::vec2(1.0f, 0.5f));  // s along the longest side, t scaled alike
}

TEST(VrmlFaceSet, TextureTransformIsBakedIntoTextureCoordinates) {
  const Scene s = read(R"(Shape { appearance Appearance { texture ImageTexture { url "sub/checker.png" }
      textureTransform TextureTransform { scale 2 3 translation 0.5 0 } }
    geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, 1 0 0, 1 1 0 ] }
      texCoord TextureCoordinate { point [ 0 0, 1 0, 1 1 ] } coordIndex [ 0 1 2 ] } })");
  const Mesh& m = *s.shapes.at(0).mesh;
  // Tc' = S x T x Tc (center 0, no rotation): translate first, then scale.
  EXPECT_EQ(m.texCoords[0], glm::vec2(1.0f, 0.0f));
  EXPECT_EQ(m.texCoords[2], glm::vec2(3.0f, 3.0f));
}

TEST(VrmlFaceSet, BadIndicesSkipFacesWithAWarning) {
  Diagnostics d;
  const Scene s = read(R"(Shape { geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, 1 0 0, 1 1 0 ] }
    coordIndex [ 0 1 2 -1, 0 1 7 -1, 0 1 -1, -5 ] } })", &d);
  EXPECT_EQ(s.shapes.at(0).mesh->indices.size(), 3u);
  EXPECT_NE(d.format().find("3 face(s) of the IndexedFaceSet"), std::string::npos);
}

TEST(VrmlGeometry, LineSetsAndPointSetsBecomeLinesAndPoints) {
  const Scene s = read(R"(
    Shape { geometry IndexedLineSet { coord Coordinate { point [ 0 0 0, 1 0 0, 1 1 0 ] } coordIndex [ 0 1 2 -1, 2 0 ] } }
    Shape { geometry PointSet { coord Coordinate { point [ 0 0 0, 5 5 5 ] } color Color { color [ 1 0 0, 0 1 0 ] } } })");
  ASSERT_EQ(s.shapes.size(), 2u);
  EXPECT_EQ(s.shapes[0].mesh->topology, Topology::kLines);
  EXPECT_EQ(s.shapes[0].mesh->indices.size(), 6u);  // segments 0-1, 1-2, 2-0
  EXPECT_EQ(s.shapes[1].mesh->topology, Topology::kPoints);
  EXPECT_EQ(s.shapes[1].mesh->colors[1], glm::vec4(0, 1, 0, 1));
}

TEST(VrmlGeometry, ElevationGridFacesUp) {
  const Scene s = read(R"(Shape { geometry ElevationGrid { xDimension 3 zDimension 2 xSpacing 2
    height [ 0 0 0, 0 1 0 ] } })");
  const Mesh& m = *s.shapes.at(0).mesh;
  EXPECT_EQ(m.indices.size(), 12u);
  for (size_t t = 0; t < m.indices.size(); t += 3) EXPECT_GT(faceNormal(m, t).y, 0.0f);
  EXPECT_EQ(localBounds(m).max, glm::vec3(4, 1, 1));
}

TEST(VrmlGeometry, DefaultExtrusionIsAClosedBox) {
  const Scene s = read("Shape { geometry Extrusion { } }");
  const Mesh& m = *s.shapes.at(0).mesh;
  EXPECT_EQ(m.indices.size(), 3u * 12);  // four sides and two caps, two triangles each
  expectOutwardWinding(m);
  expectFacesPointAwayFrom(m, glm::vec3(0, 0.5f, 0));
  EXPECT_EQ(localBounds(m).min, glm::vec3(-1, 0, -1));
  EXPECT_EQ(localBounds(m).max, glm::vec3(1, 1, 1));
  double area = 0;
  for (size_t t = 0; t < m.indices.size(); t += 3) area += 0.5 * glm::length(faceNormal(m, t));
  EXPECT_NEAR(area, 4 * 2 + 2 * 4, 1e-5);
}

TEST(VrmlGeometry, ExtrusionFollowsItsSpineScaleAndOrientation) {
  // Down the -Y axis (a collinear spine: the cross-section plane turns by 180 degrees),
  // scaled by 2 at the end and turned by 90 degrees there.
  const Scene s = read(R"(Shape { geometry Extrusion { beginCap FALSE endCap FALSE
    spine [ 0 0 0, 0 -4 0 ] scale [ 1 1, 2 0.5 ] orientation [ 0 1 0 0, 0 1 0 1.5707963 ]
    crossSection [ 1 0, 0 -1, -1 0, 0 1, 1 0 ] } })");
  const Mesh& m = *s.shapes.at(0).mesh;
  EXPECT_EQ(m.indices.size(), 3u * 8);
  expectOutwardWinding(m);
  const Bounds b = localBounds(m);
  EXPECT_NEAR(b.min.y, -4.0f, 1e-5f);
  EXPECT_NEAR(b.max.y, 0.0f, 1e-5f);
  // At the end the cross-section is 2 wide along its X and 0.5 along its Z, then turned
  // a quarter about the spine: its long axis lies along world Z.
  float endX = 0, endZ = 0;
  for (const glm::vec3& p : m.positions) {
    if (p.y < -3.9f) {
      endX = std::max(endX, std::fabs(p.x));
      endZ = std::max(endZ, std::fabs(p.z));
    }
  }
  EXPECT_NEAR(endX, 0.5f, 1e-5f);
  EXPECT_NEAR(endZ, 2.0f, 1e-5f);
}

TEST(VrmlGeometry, CurvedExtrusionKeepsItsCrossSectionUpright) {
  // A quarter circle in the XY plane: each cross-section plane is perpendicular to the
  // spine, so every point stays at the tube radius from its spine point.
  std::string spine;
  for (int i = 0; i <= 6; ++i) {
    const double a = i * 3.14159265 / 12;
    spine += std::to_string(3 * std::cos(a)) + " " + std::to_string(3 * std::sin(a)) + " 0, ";
  }
  const Scene s = read("Shape { geometry Extrusion { beginCap FALSE endCap FALSE crossSection [ 0.5 0, 0 -0.5, -0.5 0, "
                       "0 0.5, 0.5 0 ] spine [ " + spine + " ] } }");
  const Mesh& m = *s.shapes.at(0).mesh;
  expectOutwardWinding(m);
  for (const glm::vec3& p : m.positions) {
    // Distance from the spine circle (radius 3 in the XY plane) is the tube radius.
    // The two end sections follow the chord to their neighbour (6.18.2 for open
    // spines), tilted by half a segment, so they only come close.
    const float ring = std::hypot(std::hypot(p.x, p.y) - 3.0f, p.z);
    const float angle = std::atan2(p.y, p.x);
    const bool end = angle < 0.1f || angle > 1.47f;
    EXPECT_NEAR(ring, 0.5f, end ? 0.01f : 1e-4f);
  }
}

}  // namespace
}  // namespace pw::engine::vrml

#include "tests/vrml/scene_compare.h"

#include <map>

namespace pw::engine {

namespace {

// Sharing must be a bijection: the n-th distinct pointer of `a` pairs with the n-th of `b`.
template <class T>
bool samePartner(std::map<const T*, const T*>& forward, std::map<const T*, const T*>& backward, const T* a,
                 const T* b) {
  if (!a || !b) return a == b;
  auto f = forward.find(a);
  auto r = backward.find(b);
  if (f == forward.end() && r == backward.end()) {
    forward[a] = b;
    backward[b] = a;
    return true;
  }
  return f != forward.end() && r != backward.end() && f->second == b && r->second == a;
}

}  // namespace

std::string sceneDifference(const Scene& a, const Scene& b) {
  if (a.shapes.size() != b.shapes.size()) {
    return "shape count " + std::to_string(a.shapes.size()) + " vs " + std::to_string(b.shapes.size());
  }
  std::map<const Mesh*, const Mesh*> meshF, meshB;
  std::map<const Appearance*, const Appearance*> appF, appB;
  std::map<const Texture*, const Texture*> texF, texB;
  for (size_t i = 0; i < a.shapes.size(); ++i) {
    const Shape& x = a.shapes[i];
    const Shape& y = b.shapes[i];
    const std::string at = "shape " + std::to_string(i) + " (" + x.name + "): ";
    if (x.name != y.name) return at + "name '" + x.name + "' vs '" + y.name + "'";
    if (x.transform != y.transform) return at + "transforms differ";
    if (!samePartner(meshF, meshB, x.mesh.get(), y.mesh.get())) return at + "mesh sharing differs";
    if (x.mesh && !(*x.mesh == *y.mesh)) {
      const Mesh& m = *x.mesh;
      const Mesh& n = *y.mesh;
      if (m.positions != n.positions) return at + "mesh positions differ";
      if (m.normals != n.normals) return at + "mesh normals differ";
      if (m.texCoords != n.texCoords) return at + "mesh texture coordinates differ";
      if (m.colors != n.colors) return at + "mesh colours differ";
      if (m.indices != n.indices) return at + "mesh indices differ";
      return at + "mesh topology or solid flag differs";
    }
    if (!samePartner(appF, appB, x.appearance.get(), y.appearance.get())) return at + "appearance sharing differs";
    if (x.appearance) {
      if (x.appearance->material != y.appearance->material) return at + "materials differ";
      const Texture* s = x.appearance->texture.get();
      const Texture* t = y.appearance->texture.get();
      if (!samePartner(texF, texB, s, t)) return at + "texture sharing differs";
      if (s) {
        if (s->wrapS != t->wrapS || s->wrapT != t->wrapT) return at + "texture wrap modes differ";
        if (!s->image || !t->image || !(*s->image == *t->image)) return at + "texture images differ";
      }
    }
  }
  if (a.lights != b.lights) return "lights differ";
  if (a.viewpoints != b.viewpoints) return "viewpoints differ";
  if (a.navigation != b.navigation) return "navigation info differs";
  if (a.backgroundColor != b.backgroundColor) return "background colours differ";
  if (a.title != b.title) return "titles differ: '" + a.title + "' vs '" + b.title + "'";
  if (a.info != b.info) return "world info differs";
  if (a.tour != b.tour) return "tours differ";
  return {};
}

}  // namespace pw::engine

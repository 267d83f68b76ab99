// Closest point on a triangle to a point, with the feature (face, edge, vertex) it lies on.
//
// Algorithm: Voronoi-region classification of the query point p against triangle (a, b, c), as
// described in C. Ericson, "Real-Time Collision Detection" (Morgan Kaufmann 2005), §5.1.5.
// With ab = b−a, ac = c−a and the dot products d1 = ab·(p−a), d2 = ac·(p−a), d3 = ab·(p−b),
// d4 = ac·(p−b), d5 = ab·(p−c), d6 = ac·(p−c), the regions are tested in the order
//   vertex a (d1 ≤ 0, d2 ≤ 0), vertex b (d3 ≥ 0, d4 ≤ d3), edge ab (vc = d1·d4 − d3·d2 ≤ 0,
//   d1 ≥ 0, d3 ≤ 0), vertex c (d6 ≥ 0, d5 ≤ d6), edge ca (vb = d5·d2 − d1·d6 ≤ 0, d2 ≥ 0,
//   d6 ≤ 0), edge bc (va = d3·d6 − d5·d4 ≤ 0, d4 − d3 ≥ 0, d5 − d6 ≥ 0), otherwise the face
//   interior with barycentric weights (va, vb, vc)/(va + vb + vc).
// The sub-determinants va, vb, vc are (up to a common factor) the signed areas of the triangles
// formed with the projection of p, so no normal needs to be normalised and degenerate triangles
// never divide by zero in the vertex/edge branches. Written for Paddy from the mathematics above.
#pragma once

#include <paddy/contact_batch.hpp>

#include <cstdint>

namespace paddy::geometry {

// Feature of a triangle on which a closest point lies. Edge k joins corner k and corner (k+1)%3.
enum class TriFeature : std::uint8_t { Face, Edge0, Edge1, Edge2, Vertex0, Vertex1, Vertex2 };

inline bool isEdge(TriFeature f) { return f >= TriFeature::Edge0 && f <= TriFeature::Edge2; }
inline bool isVertex(TriFeature f) { return f >= TriFeature::Vertex0; }
inline int edgeIndex(TriFeature f) { return static_cast<int>(f) - static_cast<int>(TriFeature::Edge0); }
inline int vertexIndex(TriFeature f) { return static_cast<int>(f) - static_cast<int>(TriFeature::Vertex0); }

struct ClosestPoint {
  Vec3 point;
  TriFeature feature;
};

inline ClosestPoint closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a;
  const Vec3 ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {a, TriFeature::Vertex0};

  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {b, TriFeature::Vertex1};

  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double t = d1 / (d1 - d3);
    return {a + t * ab, TriFeature::Edge0};  // edge a→b
  }

  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {c, TriFeature::Vertex2};

  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double t = d2 / (d2 - d6);
    return {a + t * ac, TriFeature::Edge2};  // edge c→a
  }

  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {b + t * (c - b), TriFeature::Edge1};  // edge b→c
  }

  const double inv = 1.0 / (va + vb + vc);
  return {a + ab * (vb * inv) + ac * (vc * inv), TriFeature::Face};
}

}  // namespace paddy::geometry

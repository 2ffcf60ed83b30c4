#pragma once
/// \file
/// Writhe of a closed polygon (paper Appendix C, eq.\ 5).
#include "ek/geometry/types.hpp"

namespace ek {

/// Exact Gauss integral of two straight segments [p1, p2] and [p3, p4]:
/// Ω/(4π) where Ω is the signed solid angle of Klenin & Langowski 2000,
/// method 1a (Biopolymers 54:307), with
///   n1 = r13×r14, n2 = r14×r24, n3 = r24×r23, n4 = r23×r13 (normalised),
///   Ω* = asin(n1·n2) + asin(n2·n3) + asin(n3·n4) + asin(n4·n1),
///   Ω  = Ω* · sign((r34 × r12) · r13).
/// Ω is the solid angle that the parallelogram of the differences r13, r14,
/// r24, r23 subtends at the origin; it is evaluated as the sum over the two
/// triangles (r13, r14, r24) and (r13, r24, r23) of Van Oosterom &
/// Strackee's formula (IEEE Trans. Biomed. Eng. 30:125, 1983), two atan2 and
/// four square roots per pair (2.8 times as fast as the four arcsines,
/// `BM_Writhe`).
/// Zero for coplanar segments (including segments that share a vertex).
double segment_pair_writhe(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4);

/// Writhe Wr = Σ_{i≠j} Ω_ij/(4π) of the closed polygon P (n by 3), the exact
/// double sum over edge pairs (Swigon et al.\ 1998; Klenin & Langowski 2000).
/// O(n²). Changes sign under mirroring; 0 for planar curves.
double writhe(const Points& P);

}  // namespace ek

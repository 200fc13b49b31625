#pragma once
/// @file NozzleModel.h
/// @brief The nozzle volume used for collision tests (paper Section 3.1, Fig. 13a): its
/// bounding cone with half-angle NA about the nozzle axis (the layer normal at the tip), apex at
/// the tip, optionally cut at the nozzle length L above which the holder is a cylinder of
/// radius R about the same axis, H long (unbounded upwards when H = ∞): with a finite H the
/// printhead ends L + H above the tip (the cell's nozzle is fixed; nothing that moves with the
/// part is above it). With L = ∞ it is the paper's cone.
///
/// In coordinates of a tip p and unit axis n, a point x with h = (x - p)·n and
/// r = |x - p - h n| is inside iff h > tipClearance and
///   (h <= L and r < h tan NA)  or  (L < h <= L + H and r < R).
/// tipClearance (>= 0, default 0.1 mm) ignores material level with the tip: the nozzle's flat
/// face rides on the layer being printed, so beads of the same layer next to the tip (their tops
/// within a fraction of a layer of the tip, e.g. where the path passes a crossing the second
/// time) are not obstacles. 0 makes every point above the tip plane count.
/// tipFaceRadius (>= 0, default 0.5 mm) ignores material within that distance of the tip: it
/// lies under the nozzle's flat face around the orifice (a 0.4-0.6 mm nozzle's face is about
/// 1 mm across), which presses the bead being printed and its overlapping neighbours; it is
/// not inside the nozzle body. 0 makes the cone start at the tip point.
///
/// With a printhead mesh (nozzle/Printhead.h) the cone and holder parameters are not used: a
/// point is inside iff r < R(h), the printhead's swept radius at that height, with the same
/// two exemptions and a third that the real face needs: faceContact (>= 0, default 0.3 mm)
/// ignores material at most faceContact above the tip within the printhead's face radius +
/// faceContact of the axis: the neighbouring beads (their top a fraction of a layer higher on a
/// curved layer, their centre a bead width away) under the rim of the flat face, which presses
/// (irons) them. The cone has no face (its apex is the tip), so it does not use this.
#include "nozzle/Printhead.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace geolattice {

struct NozzleModel {
  double halfAngleDeg = 45.0;                               ///< NA, in (0, 90) degrees
  double length = std::numeric_limits<double>::infinity();  ///< L (mm, > 0), ∞ = cone only
  double holderRadius = 0.0;  ///< R (mm, >= 0), used when length is finite; 0 = no holder
  /// H (mm, > 0): the holder's length above L; ∞ = unbounded (the printhead never ends).
  double holderLength = std::numeric_limits<double>::infinity();
  double tipClearance = 0.1;   ///< material with h <= this is ignored (mm, >= 0)
  double tipFaceRadius = 0.5;  ///< material within this distance of the tip is ignored (mm, >= 0)
  /// Printhead only: material at most this high above the tip and within the face radius + this
  /// of the axis is a neighbouring bead under the face's rim (mm, >= 0).
  double faceContact = 0.3;
  /// A printhead mesh; when set it replaces the cone and the holder (null = the cone model).
  std::shared_ptr<const Printhead> printhead;
  /// Widening used by the toolpath's axis clearance to keep a margin (see widened()): the
  /// printhead's radius grows by h tan(margin) at height h. 0 for the nozzle itself.
  double printheadMarginRad = 0.0;

  /// Throws GeoLatticeError naming the bad parameter.
  void validate() const;
  /// True for the paper's unbounded cone (no length, no printhead).
  bool isConeOnly() const { return !printhead && !std::isfinite(length); }
  /// The same nozzle widened by marginDeg: the cone's half-angle grows by it (at most 89.9°), a
  /// printhead's radius by h tan(margin) at height h.
  NozzleModel widened(double marginDeg) const;
  /// Half-angle of a cone that contains the whole nozzle volume, its apex
  /// boundingApexOffset() below the tip on the axis: max(NA, atan(R / L)) with the apex at the
  /// tip for the cone model. Used for conservative bounds only.
  double boundingHalfAngleRad() const;
  /// How far below the tip (mm, >= 0) the apex of the bounding cone lies.
  double boundingApexOffset() const;
  /// Distance from the tip beyond which nothing is inside: L / cos NA for a finite nozzle
  /// without holder (holderRadius 0), max(L / cos NA, |(L + H, R)|) with a finite holder,
  /// the printhead's reach with a printhead, else ∞.
  double reach() const;
};

/// The exact point-in-nozzle test of NozzleModel in dot products (no angles), with the
/// trigonometry done once; shared by the sequencer's collision graph, the verifier and the
/// toolpath's axis clearance so that all three judge the same volume.
struct NozzleVolume {
  explicit NozzleVolume(const NozzleModel& m)
      : cos2(std::cos(m.halfAngleDeg * M_PI / 180.0) * std::cos(m.halfAngleDeg * M_PI / 180.0)),
        length(m.length),
        holder2(m.holderRadius * m.holderRadius),
        top(m.length + m.holderLength),
        clearance(m.tipClearance),
        face2(m.tipFaceRadius * m.tipFaceRadius),
        contact(m.faceContact),
        contactRadius2(m.printhead ? std::pow(m.printhead->faceRadius() + m.faceContact, 2) : 0.0),
        head(m.printhead.get()),
        headSlope(std::tan(m.printheadMarginRad)),
        headMargin(std::atan(headSlope)),
        cosHeadMargin(std::cos(headMargin)),
        sinHeadMargin(std::sin(headMargin)),
        coneAngle(m.printhead ? 0.0 : m.boundingHalfAngleRad()) {
    if (head) {
      length = -std::numeric_limits<double>::infinity();  // never the cone branch
      top = head->height();
    }
  }

  /// Is x inside the nozzle with its tip at p and unit axis n? Sets height (along n) and radial
  /// distance when it is.
  bool contains(const Eigen::Vector3d& p, const Eigen::Vector3d& n, const Eigen::Vector3d& x,
                double* height = nullptr, double* radial = nullptr) const {
    const Eigen::Vector3d d = x - p;
    const double h = d.dot(n);
    if (!(h > clearance)) {
      return false;
    }
    const double d2 = d.squaredNorm();
    if (d2 <= face2) {
      return false;
    }
    const double r2 = std::max(0.0, d2 - h * h);
    // angle(d, n) < NA (h > 0) in the cone, r < R along the holder, r < R(h) in a printhead
    bool inside;
    if (head) {
      if (h <= contact && r2 <= contactRadius2) {
        return false;  // a neighbouring bead under the face's rim
      }
      const double R = head->radiusAt(h) + h * headSlope;
      inside = h <= top && r2 < R * R;
    } else {
      inside = h <= length ? h * h > d2 * cos2 : h <= top && r2 < holder2;
    }
    if (inside && height) {
      *height = h;
    }
    if (inside && radial) {
      *radial = std::sqrt(r2);
    }
    return inside;
  }

  /// Conservative test for a ball whose points lie at heights within h ± slack and at least
  /// r - slack from the axis: false when no such point can be inside the printhead's swept
  /// solid. Always true for the cone model (its bounding cone does this job).
  bool mayContainBall(double h, double r, double slack) const {
    if (!head) {
      return true;
    }
    const double hi = h + slack;
    if (hi <= clearance) {
      return false;
    }
    return head->maxRadiusBetween(h - slack, hi) + std::max(hi, 0.0) * headSlope > r - slack;
  }

  /// Turning the axis so that a point at distance rho from the tip is this far (rad) from it
  /// puts the point outside (cone: NA, with a holder the bounding angle max(NA, atan(R / L));
  /// printhead: its tabulated clear angle, plus the margin).
  double clearAngleAt(double rho) const {
    return head ? head->clearAngleAt(rho) + headMargin : coneAngle;
  }
  /// The largest clearAngleAt over distances in [rho0, rho1].
  double maxClearAngleBetween(double rho0, double rho1) const {
    return head ? head->maxClearAngleBetween(rho0, rho1) + headMargin : coneAngle;
  }
  /// Its cosine, without trigonometry for a printhead (-1 when it reaches π).
  double cosMaxClearAngleBetween(double rho0, double rho1) const {
    if (!head) {
      return std::cos(coneAngle);
    }
    const double c = head->cosMaxClearAngleBetween(rho0, rho1);
    const double s = std::sqrt(std::max(0.0, 1.0 - c * c));  // the angle is in [0, π]
    if (c < -cosHeadMargin) {
      return -1.0;  // angle + margin >= π
    }
    return c * cosHeadMargin - s * sinHeadMargin;  // cos(angle + margin)
  }

  double cos2, length, holder2, top, clearance, face2, contact, contactRadius2;
  const Printhead* head;  ///< owned by the NozzleModel this volume was made from
  double headSlope;
  double headMargin, cosHeadMargin, sinHeadMargin;  ///< atan(headSlope): the margin as an angle
  double coneAngle;  ///< the parametric model's bounding half-angle (rad)
};

}  // namespace geolattice

// Cross-sections of 2D frame members. Properties are computed from dimensions, never typed in.
// Local axes: x' along the member, y' in the analysis plane (depth direction), z' out of plane
// (width). Depth-wise quantities (I about z', half depth c) describe in-plane bending.
#pragma once

namespace dmi {

enum class SectionKind { rectangle, pipe, tapered_rectangle, box, i_section };

class Section {
 public:
  static Section rectangle(double width, double depth);               // b x h (m)
  static Section pipe(double diameter, double wall_thickness);         // circular hollow D x t (m)
  // Rectangle whose depth varies linearly from depth_start (s = 0) to depth_end (s = 1) along the
  // member; the centre-line runs through mid-depth (a symmetric taper).
  static Section tapered(double width, double depth_start, double depth_end);
  // Rectangular hollow section b x h with walls t all round (EN 10219 / 10210 RHS, square corners).
  static Section box(double width, double depth, double wall_thickness);
  // Doubly symmetric I (or H) section: flanges b x t_f, web (h - 2 t_f) x t_w in the plane of bending (the strong axis
  // bends in-plane), square corners (no root fillets).
  static Section i_section(double flange_width, double depth, double flange_thickness, double web_thickness);

  SectionKind kind() const { return kind_; }
  // Properties at the fraction s in [0, 1] of the member length.
  double depth(double s) const;        // m, extreme-fibre to extreme-fibre in-plane
  double half_depth(double s) const { return 0.5 * depth(s); }  // c (m): centroid to each surface
  double width(double s) const;        // m, out of plane (pipe: D)
  double wall_thickness() const;       // m, pipe or box wall t; the I section's flange t_f (0 for solid rectangles)
  double web_thickness() const;        // m, the I section's web t_w; a box's walls t (0 otherwise)
  bool hollow() const { return kind_ == SectionKind::pipe || kind_ == SectionKind::box; }
  bool thin_walled() const { return hollow() || kind_ == SectionKind::i_section; }
  double area(double s) const;         // A (m^2)
  double inertia(double s) const;      // I about the out-of-plane axis (m^4)
  // For members bent out of the plane and twisted (space frames): I about the in-plane axis y' (rectangle h b^3 / 12,
  // pipe = inertia) and the St Venant torsion constant J (m^4): pipe pi (D^4 - d^4) / 32 (exact); rectangle
  // beta(b/t) b t^3, t the smaller side, by the series of Timoshenko & Goodier (1970, sec. 109, eq. 159).
  double inertia_y(double s) const;
  double torsion_constant(double s) const;
  // Torsional section modulus W_t = T / tau_max (m^3): pipe J / (D / 2); rectangle J / (k t) with
  // k = 1 - (8 / pi^2) sum_{n odd} 1 / (n^2 cosh(n pi b / (2 t))) (Timoshenko & Goodier 1970, sec. 109).
  double torsion_modulus(double s) const;
  // Shear coefficient kappa: A_s = kappa A (Timoshenko). Rectangle 5/6; thin pipe 1/2 (Cowper 1966 limits); box and I
  // the walls parallel to the shear over the whole area (the web carries the shear).
  double shear_coefficient() const;
  // Peak shear stress over the section = factor * V / A: rectangle 3/2, pipe 2 (thin wall, V Q / (I t)); box and I
  // V Q / (I t) at the neutral axis, Q the first moment of the half section, t the walls' width there.
  double shear_stress_factor() const;
  // Shear stress at the in-plane coordinate y' (|y'| <= h/2) under a unit shear force along y', Q(y') / (I t(y')) (1/m^2),
  // for the solid and open or closed thin-walled sections (Jourawski); pipes: 2 / A sqrt(1 - (2y'/D)^2).
  double shear_flow_stress(double s, double y) const;
  // Plastic section modulus for in-plane bending W_pl (m^3): the first moment of each half about the axis.
  double plastic_modulus(double s) const;
  // The same for bending out of the plane (about y'; 3D): rectangle h b^2 / 4, pipe as in-plane, box and I from their
  // plates.
  double plastic_modulus_y(double s) const;

 private:
  SectionKind kind_ = SectionKind::rectangle;
  double b_ = 0, h0_ = 0, h1_ = 0;  // width, depth at s = 0 and 1 (pipe: D = h0_, t = b_)
  double t_ = 0, tw_ = 0;           // box: wall, I: flange and web
  // The section's width at y' (across the depth): b in the flanges, the walls' width between them.
  double width_at(double s, double y) const;
  // First moment about the neutral axis of the part of the section beyond y' (m^3).
  double first_moment_beyond(double s, double y) const;
};

}  // namespace dmi

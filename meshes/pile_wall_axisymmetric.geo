// Axisymmetric pile wall in the (r, z) plane: x = r, y = z (up), toe at z = 0, head at z = L.
//
// Parameters, normally defined by fem/axisymmetric_mesher.cpp in a generated .geo that is
// merged just before this file (the parser keeps variables from one merge to the next):
//   st_z[], st_ri[], st_ro[]  stations, toe first: elevation, inner and outer radius (m)
//   nz[]                      axial divisions of each interval between consecutive stations
//   nr                        divisions through the wall, the same in every interval
// Opened on its own (e.g. in the gmsh GUI) it meshes the small demo tube below.
If (!Exists(st_z))
  st_z[] = {0, 5, 5.04, 10};
  st_ri[] = {0.94, 0.94, 0.95, 0.95};
  st_ro[] = {1, 1, 1, 1};
  nz[] = {50, 1, 50};
  nr = 2;
EndIf

n_st = #st_z[];
If (n_st < 2 || #st_ri[] != n_st || #st_ro[] != n_st || #nz[] != n_st - 1 || nr < 1)
  Error("pile_wall_axisymmetric.geo: need >= 2 stations, matching st_ri/st_ro, n-1 nz, nr >= 1");
EndIf

// A station repeated at the same z gives a zero-height interval; it has no area, so skip it.
z_tol = 1e-12 * (Fabs(st_z[n_st - 1] - st_z[0]) + 1);

// The bottom line of the next surface is the top line of the previous one, so the
// intervals share nodes. A new bottom line is only made when the radii changed at a
// skipped zero-height interval (a step), where no conforming connection exists.
// (The parser evaluates every operand of || and &&, so bot_ri/bot_ro must exist up front.)
have_bottom = 0;
bot_ri = -1;
bot_ro = -1;
wall_surfaces[] = {};
For i In {0 : n_st - 2}
  If (st_z[i + 1] - st_z[i] > z_tol)
    If (!have_bottom || st_ri[i] != bot_ri || st_ro[i] != bot_ro)
      bot_in = newp;
      Point(bot_in) = {st_ri[i], st_z[i], 0};
      bot_out = newp;
      Point(bot_out) = {st_ro[i], st_z[i], 0};
      bot_line = newl;
      Line(bot_line) = {bot_in, bot_out};
      If (!have_bottom)
        toe_line = bot_line;
      EndIf
    EndIf

    top_in = newp;
    Point(top_in) = {st_ri[i + 1], st_z[i + 1], 0};
    top_out = newp;
    Point(top_out) = {st_ro[i + 1], st_z[i + 1], 0};
    top_line = newl;
    Line(top_line) = {top_in, top_out};
    inner_line = newl;
    Line(inner_line) = {bot_in, top_in};
    outer_line = newl;
    Line(outer_line) = {bot_out, top_out};

    // Counter-clockwise loop in (r, z): the surface faces the viewer, so its quads are CCW too.
    loop = newll;
    Curve Loop(loop) = {bot_line, outer_line, -top_line, -inner_line};
    wall = news;
    Plane Surface(wall) = {loop};

    Transfinite Curve{bot_line, top_line} = nr + 1;
    Transfinite Curve{inner_line, outer_line} = nz[i] + 1;
    Transfinite Surface{wall} = {bot_in, bot_out, top_out, top_in};
    Recombine Surface{wall};
    wall_surfaces[] += wall;

    have_bottom = 1;
    bot_in = top_in;
    bot_out = top_out;
    bot_line = top_line;
    bot_ri = st_ri[i + 1];
    bot_ro = st_ro[i + 1];
  EndIf
EndFor

If (!have_bottom)
  Error("pile_wall_axisymmetric.geo: all intervals have zero height");
EndIf

// Named groups for anyone writing the mesh to a file; the C++ mesher reads the model directly.
Physical Surface("wall") = wall_surfaces[];
Physical Curve("toe") = {toe_line};
Physical Curve("head") = {bot_line};

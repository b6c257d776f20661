// Sphere resting on a plate, meridian half-plane of the axisymmetric model.
// Coordinates: x = r (radial, axis at r = 0), y = z (axial, up). SI units (m).
//
// Parameters (override with `gmsh -setnumber NAME VALUE`):
//   R        sphere radius                                   [m]
//   g0       initial gap between sphere and plate (>= 0)     [m]
//   Rp       plate radius                                    [m]
//   H        plate thickness                                 [m]
//   rc       radius of the contact surfaces (both bodies)    [m]
//   hc       element size at and around the contact point    [m]
//   rz       radius of the zone kept at size hc              [m]
//   growth   growth of the element size per element beyond rz [-] (> 1)
//   hmax     largest element size                            [m]
//   plate    1: mesh the plate; 0: the plate is the rigid plane z = 0 (not meshed)
//   hemisphere 1: mesh only the lower hemisphere, its base (the equatorial
//            plane) a boundary of its own (indentation); 0: the whole sphere
//
// The sphere's bottom point and the plate's top centre may coincide (g0 = 0):
// the two bodies are meshed separately, so geometric coherence is switched off.
Geometry.AutoCoherence = 0;

DefineConstant[ R = 0.01452, g0 = 0, Rp = 0.1, H = 0.05, rc = 2.5e-3,
                hc = 50e-6, rz = 1.5e-3, growth = 1.2, hmax = 5e-3,
                plate = 1, hemisphere = 0 ];

zc = R + g0;                         // sphere centre height
zr = zc - Sqrt(R * R - rc * rc);     // height of the end of the sphere's contact arc

// ---- sphere ----
Point(1) = {0, zc, 0};               // centre (arc construction only)
Point(2) = {0, g0, 0};               // lowest point = first contact point
Point(3) = {rc, zr, 0};              // end of the contact surface
Point(4) = {R, zc, 0};               // equator
Circle(1) = {2, 1, 3};               // contact surface
Circle(2) = {3, 1, 4};               // free surface (lower part)
If (hemisphere)
  Line(5)   = {4, 1};                // base: the equatorial plane
  Line(4)   = {1, 2};                // axis
  Curve Loop(1) = {1, 2, 5, 4};
Else
  Point(5) = {0, zc + R, 0};         // top
  Circle(3) = {4, 1, 5};             // free surface (upper part)
  Line(4)   = {5, 2};                // axis
  Curve Loop(1) = {1, 2, 3, 4};
EndIf
Plane Surface(1) = {1};

If (plate)
// ---- plate ----
Point(11) = {0, 0, 0};
Point(12) = {rc, 0, 0};
Point(13) = {Rp, 0, 0};
Point(14) = {Rp, -H, 0};
Point(15) = {0, -H, 0};
Line(11) = {11, 12};                 // contact surface
Line(12) = {12, 13};                 // top free surface
Line(13) = {13, 14};                 // side
Line(14) = {14, 15};                 // bottom
Line(15) = {15, 11};                 // axis
Curve Loop(2) = {11, 12, 13, 14, 15};
Plane Surface(2) = {2};

EndIf

// ---- physical groups: tags are the boundary / material ids read by impact-fem ----
Physical Curve("sphere contact surface", 2) = {1};
Physical Surface("sphere", 1)               = {1};
If (hemisphere)
  Physical Curve("sphere free surface", 3)  = {2};
  Physical Curve("sphere base", 8)          = {5};
Else
  Physical Curve("sphere free surface", 3)  = {2, 3};
EndIf
If (plate)
  Physical Curve("axis", 1)                  = {4, 15};
  Physical Curve("plate contact surface", 4)  = {11};
  Physical Curve("plate top free surface", 5) = {12};
  Physical Curve("plate side", 6)             = {13};
  Physical Curve("plate bottom", 7)           = {14};
  Physical Surface("plate", 2)                = {2};
Else
  Physical Curve("axis", 1)                  = {4};
EndIf

// ---- size field: hc up to distance rz from the contact point, then growing ----
// Sizes are doubled here because the final subdivision into quadrilaterals
// halves every element: the mesh written has size hc at the contact point and
// neighbouring elements differ by the factor `growth` beyond rz.
Field[1] = Distance;
If (plate)
  Field[1].PointsList = {2, 11};
Else
  Field[1].PointsList = {2};
EndIf
Field[2] = MathEval;
Field[2].F = Sprintf("Min(%g, %g + %g * Max(0, F1 - %g))",
                     2 * hmax, 2 * hc, 2 * (growth - 1), rz);
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

// ---- quadrilaterals only (deal.II) ----
Mesh.Algorithm = 6;                  // frontal-Delaunay (8, its quad variant, crashes gmsh 4.8 here)
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;     // blossom
Mesh.SubdivisionAlgorithm = 1;       // split the remaining triangles: all quads
Mesh.ElementOrder = 1;
Mesh.MshFileVersion = 2.2;

// caustic_ball.pov: the scene of caustic_ball.sc for POV-Ray 3.7 with photons (same coordinates: the
// camera's right vector is negated, POV-Ray's way to render a right-handed scene; angle is horizontal).
// A photon target casts no filtered shadow (checked: without photons the ball's shadow is lit through).
// No Fresnel term (the glass passes everything, as §9.2's `transparent 1 1 1`), no ambient, no fade.
#version 3.7;
global_settings {
  assumed_gamma 1.0 ambient_light rgb 0 max_trace_level 10
  photons { count 4000000 autostop 0 jitter 0.4 max_trace_level 10 }
}
camera { perspective location <0,6,6> up y right -x*1.333333 angle 39.3201 look_at <0,-3,0> }
background { rgb 0 }
light_source { <0,10,0> rgb 1 spotlight point_at <0,0,0> radius 5 falloff 5 tightness 0
  photons { refraction on reflection off } }
sphere { 0, 1 pigment { rgbf <1,1,1,1> } finish { ambient 0 diffuse 0 } interior { ior 1.5 }
  photons { target refraction on reflection off collect off } }
box { <-20,-4,-20>, <20,-3,20> pigment { rgb 0.8 } finish { ambient 0 diffuse 1 } }

// small.pov: the scene of small.sc for POV-Ray 3.7 (same coordinates: the camera's right
// vector is negated, POV-Ray's way to render a right-handed scene; angle is horizontal).
#version 3.7;
global_settings { max_trace_level 5 assumed_gamma 1.0 ambient_light rgb 0.2 }
camera { perspective location <0,3.5,9> up y right -x*1.333333 angle 57.8224 look_at <0,0.8,0> }
background { rgb <0.4,0.55,0.8> }
light_source { <5,8,6> rgb <0.8,0.8,0.8> }
light_source { <-6,5,3> rgb <0.4,0.4,0.45> }
box { -0.5, 0.5 matrix <12,0,-0,0,0.2,0,0,0,12,0,-0.1,0> pigment { rgb <0.8,0.8,0.75> } finish { ambient 0.2 diffuse 1 phong 0.1 phong_size 10 reflection 0.2 } }
sphere { 0, 0.5 matrix <1.6,0,-0,0,1.6,0,0,0,1.6,-1.6,0.8,0> pigment { rgb <0.1,0.1,0.1> } finish { ambient 0.2 diffuse 1 phong 0.8 phong_size 80 reflection 0.8 } }
sphere { 0, 0.5 matrix <1.4,0,-0,0,1.4,0,0,0,1.4,0.9,0.7,1.2> pigment { rgbt <0.05,0.05,0.05,0.85> } finish { ambient 0.2 diffuse 1 phong 0.9 phong_size 100 } interior { ior 1.5 } }
sphere { 0, 0.5 matrix <1,0,-0,0,1,0,0,0,1,2.6,0.5,-1> pigment { rgb <0.9,0.2,0.2> } finish { ambient 0.2 diffuse 1 phong 0.5 phong_size 40 } }
cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <1,0,-0,0,2,0,0,0,1,-0.3,1,-2.2> pigment { rgb <0.2,0.7,0.3> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
cone { <0,-0.5,0>, 0.5, <0,0.5,0>, 0 matrix <1,0,-0,0,1.5,0,0,0,1,2.2,0.75,1.8> pigment { rgb <0.9,0.7,0.1> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
box { -0.5, 0.5 matrix <0.866025,0,-0.5,0,1,0,0.5,0,0.866025,-3.2,0.5,1.6> pigment { rgb <0.2,0.3,0.9> } finish { ambient 0.2 diffuse 1 phong 0.4 phong_size 30 } }
box { -0.5, 0.5 matrix <0.424264,0,-0.424264,0,2,0,0.424264,0,0.424264,3.6,1,-3> pigment { rgb <0.7,0.7,0.7> } finish { ambient 0.2 diffuse 1 phong 0.5 phong_size 50 reflection 0.6 } }
sphere { 0, 0.5 matrix <0.7,0,-0,0,0.7,0,0,0,0.7,-2.6,0.35,-2.6> pigment { rgb <0.8,0.4,0.9> } finish { ambient 0.2 diffuse 1 phong 0.5 phong_size 60 } }
cylinder { <0,-0.5,0>, <0,0.5,0>, 0.5 matrix <1.2,0,-0,0,0.5,0,0,0,1.2,0.4,0.25,3> pigment { rgb <0.9,0.5,0.3> } finish { ambient 0.2 diffuse 1 phong 0.3 phong_size 20 reflection 0.3 } }

// mirrors.pov: the scene of mirrors.sc for POV-Ray 3.7 (same coordinates: the camera's right
// vector is negated, POV-Ray's way to render a right-handed scene; angle is horizontal).
#version 3.7;
global_settings { max_trace_level 5 assumed_gamma 1.0 ambient_light rgb 0.2 }
camera { perspective location <0,4,10> up y right -x*1.333333 angle 57.8224 look_at <0,0.5,0> }
background { rgb <0.4,0.55,0.8> }
light_source { <5,8,6> rgb <0.8,0.8,0.8> }
light_source { <-6,5,3> rgb <0.4,0.4,0.45> }
box { -0.5, 0.5 matrix <14,0,0,0,0.2,0,0,0,14,0,-0.1,0> pigment { rgb <0.5,0.5,0.5> } finish { ambient 0.2 diffuse 1 phong 0.1 phong_size 10 reflection 0.5 } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,-4,0.7,-4> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.9,0.9,0.9> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,-4,0.7,-2> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.9,0.8,0.6> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,-4,0.7,0> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.7,0.85,0.9> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,-4,0.7,2> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.9,0.9,0.9> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,-4,0.7,4> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.9,0.8,0.6> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,-2,0.7,-4> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.7,0.85,0.9> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,-2,0.7,-2> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.9,0.9,0.9> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,-2,0.7,0> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.9,0.8,0.6> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,-2,0.7,2> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.7,0.85,0.9> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,-2,0.7,4> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.9,0.9,0.9> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,0,0.7,-4> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.9,0.8,0.6> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,0,0.7,-2> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.7,0.85,0.9> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,0,0.7,0> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.9,0.9,0.9> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,0,0.7,2> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.9,0.8,0.6> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,0,0.7,4> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.7,0.85,0.9> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,2,0.7,-4> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.9,0.9,0.9> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,2,0.7,-2> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.9,0.8,0.6> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,2,0.7,0> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.7,0.85,0.9> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,2,0.7,2> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.9,0.9,0.9> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,2,0.7,4> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.9,0.8,0.6> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,4,0.7,-4> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.7,0.85,0.9> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,4,0.7,-2> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.9,0.9,0.9> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,4,0.7,0> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.9,0.8,0.6> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,4,0.7,2> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.7,0.85,0.9> } }
sphere { 0, 0.5 matrix <1.4,0,0,0,1.4,0,0,0,1.4,4,0.7,4> pigment { rgb <0.05,0.05,0.05> } finish { ambient 0.2 diffuse 1 phong 0.6 phong_size 80 reflection <0.9,0.9,0.9> } }

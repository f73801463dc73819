# small.sc: ten objects on a floor, mirror and glass spheres, two point lights (bench/compare_povray.sh).
# bench/scenes/small.pov is the same scene for POV-Ray 3.7.
camera [ eye 0 3.5 9  focus 0 0.8 0  up 0 1 0  angle 45 ]
background [ color 0.4 0.55 0.8 ]
light [ type point  position 5 8 6  color 0.8 0.8 0.8 ]
light [ type point  position -6 5 3  color 0.4 0.4 0.45 ]
light [ ambient 0.2 0.2 0.2 ]

mastersubgraph root [
  trans [ translate 0 -0.1 0  scale 12 0.2 12  object cube [ diffuse 0.8 0.8 0.75 specular 0.1 0.1 0.1 shine 10 reflect 0.2 0.2 0.2  ambient 0.2 0.2 0.2 ] ]
  trans [ translate -1.6 0.8 0  scale 1.6 1.6 1.6  object sphere [ diffuse 0.1 0.1 0.1 specular 0.8 0.8 0.8 shine 80 reflect 0.8 0.8 0.8  ambient 0.2 0.2 0.2 ] ]
  trans [ translate 0.9 0.7 1.2  scale 1.4 1.4 1.4  object sphere [ diffuse 0.05 0.05 0.05 specular 0.9 0.9 0.9 shine 100 transparent 0.85 0.85 0.85 ior 1.5  ambient 0.2 0.2 0.2 ] ]
  trans [ translate 2.6 0.5 -1  scale 1 1 1  object sphere [ diffuse 0.9 0.2 0.2 specular 0.5 0.5 0.5 shine 40  ambient 0.2 0.2 0.2 ] ]
  trans [ translate -0.3 1 -2.2  scale 1 2 1  object cylinder [ diffuse 0.2 0.7 0.3 specular 0.4 0.4 0.4 shine 30  ambient 0.2 0.2 0.2 ] ]
  trans [ translate 2.2 0.75 1.8  scale 1 1.5 1  object cone [ diffuse 0.9 0.7 0.1 specular 0.4 0.4 0.4 shine 30  ambient 0.2 0.2 0.2 ] ]
  trans [ translate -3.2 0.5 1.6  rotate 0 1 0 30  scale 1 1 1  object cube [ diffuse 0.2 0.3 0.9 specular 0.4 0.4 0.4 shine 30  ambient 0.2 0.2 0.2 ] ]
  trans [ translate 3.6 1 -3  rotate 0 1 0 45  scale 0.6 2 0.6  object cube [ diffuse 0.7 0.7 0.7 reflect 0.6 0.6 0.6 specular 0.5 0.5 0.5 shine 50  ambient 0.2 0.2 0.2 ] ]
  trans [ translate -2.6 0.35 -2.6  scale 0.7 0.7 0.7  object sphere [ diffuse 0.8 0.4 0.9 specular 0.5 0.5 0.5 shine 60  ambient 0.2 0.2 0.2 ] ]
  trans [ translate 0.4 0.25 3  scale 1.2 0.5 1.2  object cylinder [ diffuse 0.9 0.5 0.3 specular 0.3 0.3 0.3 shine 20 reflect 0.3 0.3 0.3  ambient 0.2 0.2 0.2 ] ]
]

# quadrics.sc: spheres, cylinders and cones (scaled non-uniformly, turned, instanced) on a floor,
# lit by an emissive sphere and a dim uniform sky; for `whitted --mode path` against Blender
# Cycles (bench/compare_cycles.sh), which tessellates what whitted intersects exactly.
camera [ eye 0 2.6 6.5  focus 0 0.7 0  up 0 1 0  angle 40 ]
background [ color 0.05 0.06 0.08 ]

mastersubgraph post [
  trans [ translate 0 0.6 0  scale 0.5 1.2 0.5  object cylinder [ diffuse 0.8 0.8 0.8 ] ]
  trans [ translate 0 1.4 0  scale 0.7 0.4 0.7  object cone [ diffuse 0.8 0.3 0.2 ] ]
]

mastersubgraph root [
  trans [ translate 0 -0.1 0  scale 12 0.2 12  object cube [ diffuse 0.7 0.7 0.7 ] ]
  # the light: an emissive sphere of radius 0.4 above and behind the objects
  trans [ translate 1.2 3 -1.5  scale 0.8 0.8 0.8  object sphere [ diffuse 0 0 0  emit 30 28 24 ] ]
  trans [ translate -1.5 0.7 0  scale 1.4 1.4 1.4  object sphere [ diffuse 0.75 0.25 0.2 ] ]
  trans [ translate 0.2 0.45 0.9  scale 1.4 0.9 0.9  object sphere [ diffuse 0.2 0.5 0.8 ] ]
  trans [ translate 1.7 0.5 0.2  rotate 0 0 1 20  scale 0.8 1 0.8  object cylinder [ diffuse 0.3 0.75 0.3 ] ]
  trans [ translate -0.2 0.6 -1  rotate 1 0 0 -10  scale 1 1.2 1  object cone [ diffuse 0.9 0.75 0.2 ] ]
  trans [ translate -2.6 0 -1.6  subgraph post ]
  trans [ translate 2.8 0 -1.2  rotate 0 1 0 30  subgraph post ]
  trans [ translate 0.9 0.25 1.9  rotate 0 0 1 90  scale 0.5 0.9 0.5  object cylinder [ diffuse 0.85 0.85 0.85 ] ]
]

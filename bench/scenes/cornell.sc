# cornell.sc: a Cornell box made of cubes, lit by an emissive ceiling panel (a flat cube) alone;
# for `whitted --mode path` against Blender Cycles (bench/compare_cycles.sh). Interior: x, z in
# [-1, 1], y in [0, 2]; the front (z = +1) is open; walls are slabs 0.1 thick outside it.
camera [ eye 0 1 3.9  focus 0 1 0  up 0 1 0  angle 38 ]
background [ color 0 0 0 ]

mastersubgraph root [
  # floor, ceiling, back wall (white), left wall (red), right wall (green)
  trans [ translate 0 -0.05 0  scale 2.2 0.1 2  object cube [ diffuse 0.73 0.73 0.73 ] ]
  trans [ translate 0 2.05 0  scale 2.2 0.1 2  object cube [ diffuse 0.73 0.73 0.73 ] ]
  trans [ translate 0 1 -1.05  scale 2.2 2.2 0.1  object cube [ diffuse 0.73 0.73 0.73 ] ]
  trans [ translate -1.05 1 0  scale 0.1 2.2 2  object cube [ diffuse 0.63 0.065 0.05 ] ]
  trans [ translate 1.05 1 0  scale 0.1 2.2 2  object cube [ diffuse 0.14 0.45 0.091 ] ]
  # the light: a panel 0.5 x 0.5 reaching 0.02 below the ceiling (its upper half is inside the slab)
  trans [ translate 0 2 0  scale 0.5 0.04 0.5  object cube [ diffuse 0.78 0.78 0.78  emit 17 12 4 ] ]
  # a tall block and a short one, turned about the vertical
  trans [ translate -0.33 0.6 -0.3  rotate 0 1 0 17  scale 0.58 1.2 0.58  object cube [ diffuse 0.73 0.73 0.73 ] ]
  trans [ translate 0.35 0.3 0.3  rotate 0 1 0 -17  scale 0.58 0.6 0.58  object cube [ diffuse 0.73 0.73 0.73 ] ]
]

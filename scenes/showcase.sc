# showcase.sc -- the bundled whitted showcase scene.
#
# A small courtyard on a checkered floor: a framed mirror, a glass sphere and a
# tinted glass cube, a chrome ball, a spot-lit red cone, a gold cylinder lying on
# its side, a sheared blue "egg" (matrixRC), and three instanced pillars.
#
# Features used: all four shapes (cube, cylinder, cone, sphere); translate, rotate,
# non-uniform scale and matrixRC; point lights with attenuation (function c l q),
# two directional lights and two spotlights (aperture + exponent); hard shadows and a
# tinted shadow through coloured glass; a mirror (reflect); glass (transparent +
# ior); specular highlights; a background colour; instancing through the
# mastersubgraphs `pillar` and `tiles3`, each used several times via `subgraph`.
# 40 objects in all. No textures.
# The distribution effects of scene-format.md §9.1, seen with --spp > 1: soft shadows
# from the key light (a disc, `radius`), depth of field (camera `aperture`, in focus
# at the `focus` point), glossy floor tiles and a brushed gold cylinder (`gloss`).
# With one sample per pixel they fall back to the sharp lab model.
#
# Render: whitted scenes/showcase.sc -o showcase.png --width 800 --height 600 --spp 16

background [
  color 0.32 0.45 0.65
]

camera [
  eye 7 4.6 10.5
  focus -0.2 1.1 -0.6
  up 0 1 0
  angle 42
  near-far 0.1 100
  aperture 0.15
]

# Key light: warm point light, up and to the right, gently attenuated.
light [
  type point
  position 6 9 6
  color 1.5 1.4 1.2
  function 1 0.02 0.004
  radius 1.2
]

# Fill light: dim, cool, from the left.
light [
  type point
  position -8 5 4
  color 0.45 0.5 0.65
  function 0.5 0 0.01
]

# Sky light: a weak directional "sun" slanting down from the back left.
light [
  type directional
  direction 0.4 -1 0.3
  color 0.3 0.3 0.33
]

# Spotlight aimed down at the red cone.
light [
  type spotlight
  position -0.5 7 1.5
  direction 0 -1 -0.5
  color 1.2 1.1 0.9
  function 1 0 0.005
  aperture 22
  exponent 6
]

# Low evening light: a second, warm directional light grazing in from the right.
light [
  type directional
  direction -1 -0.35 -0.25
  color 0.22 0.16 0.08
]

# Second spotlight: a soft warm pool on the gold cylinder, from the front right.
light [
  type spotlight
  position 6 6 4
  direction -0.45 -0.7 -0.55
  color 0.9 0.75 0.45
  function 1 0 0.004
  aperture 16
  exponent 2
]

# Global ambient intensity (scales every object's ambient colour).
light [
  ambient 0.6 0.6 0.65
]

# Three dark floor tiles, 2 units apart along x (a third of a checker row).
mastersubgraph tiles3 [
  trans [
    translate 0 0 0
    scale 2 0.02 2
    object cube [
      ambient 0.03 0.03 0.04
      diffuse 0.18 0.18 0.22
      specular 0.3 0.3 0.3
      shine 20
      reflect 0.15 0.15 0.15
      gloss 60
    ]
  ]
  trans [
    translate 4 0 0
    scale 2 0.02 2
    object cube [
      ambient 0.03 0.03 0.04
      diffuse 0.18 0.18 0.22
      specular 0.3 0.3 0.3
      shine 20
      reflect 0.15 0.15 0.15
      gloss 60
    ]
  ]
  trans [
    translate 8 0 0
    scale 2 0.02 2
    object cube [
      ambient 0.03 0.03 0.04
      diffuse 0.18 0.18 0.22
      specular 0.3 0.3 0.3
      shine 20
      reflect 0.15 0.15 0.15
      gloss 60
    ]
  ]
]

# A classical pillar standing on y = 0: plinth, shaft, capital and an orb.
mastersubgraph pillar [
  trans [
    translate 0 0.15 0
    scale 1.1 0.3 1.1
    object cube [
      ambient 0.08 0.075 0.07
      diffuse 0.8 0.75 0.7
    ]
  ]
  trans [
    translate 0 1.8 0
    scale 0.6 3 0.6
    object cylinder [
      ambient 0.08 0.075 0.07
      diffuse 0.85 0.8 0.75
      specular 0.2 0.2 0.2
      shine 10
    ]
  ]
  trans [
    translate 0 3.45 0
    scale 1 0.3 1
    object cube [
      ambient 0.08 0.075 0.07
      diffuse 0.8 0.75 0.7
    ]
  ]
  trans [
    translate 0 3.95 0
    scale 0.7 0.7 0.7
    object sphere [
      ambient 0.09 0.05 0.01
      diffuse 0.9 0.5 0.1
      specular 0.8 0.8 0.8
      shine 60
    ]
  ]
]

mastersubgraph root [
  # Floor: a large flat slab whose top face is y = 0.
  trans [
    translate 0 -0.5 0
    scale 30 1 30
    object cube [
      ambient 0.08 0.08 0.075
      diffuse 0.78 0.76 0.7
    ]
  ]

  # Checker: six rows of three dark tiles, alternate rows shifted by one tile.
  trans [ translate -5 0.01 -5  subgraph tiles3 ]
  trans [ translate -3 0.01 -3  subgraph tiles3 ]
  trans [ translate -5 0.01 -1  subgraph tiles3 ]
  trans [ translate -3 0.01  1  subgraph tiles3 ]
  trans [ translate -5 0.01  3  subgraph tiles3 ]
  trans [ translate -3 0.01  5  subgraph tiles3 ]

  # Instanced pillars (the last one is squatter and wider: non-uniform scale).
  trans [ translate 4.5 0 -4.5  subgraph pillar ]
  trans [ translate -5.2 0 -3.8  subgraph pillar ]
  trans [ translate 5.2 0 -2.2  scale 1.2 0.8 1.2  subgraph pillar ]

  # The mirror: a thin slab turned 20 degrees toward the camera, on two posts.
  trans [
    translate -1.5 2.1 -5.4
    rotate 0 1 0 20
    scale 4 3.2 0.08
    object cube [
      diffuse 0.04 0.04 0.04
      specular 1 1 1
      shine 200
      reflect 0.88 0.9 0.92
    ]
  ]
  trans [
    translate -1.5 0 -5.4
    rotate 0 1 0 20
    translate -2.15 1.9 0
    scale 0.22 3.8 0.22
    object cylinder [
      ambient 0.03 0.02 0.01
      diffuse 0.35 0.2 0.1
      specular 0.4 0.4 0.4
      shine 30
    ]
  ]
  trans [
    translate -1.5 0 -5.4
    rotate 0 1 0 20
    translate 2.15 1.9 0
    scale 0.22 3.8 0.22
    object cylinder [
      ambient 0.03 0.02 0.01
      diffuse 0.35 0.2 0.1
      specular 0.4 0.4 0.4
      shine 30
    ]
  ]

  # Glass sphere, radius 1, resting on the floor.
  trans [
    translate 1.3 1 2.1
    scale 2 2 2
    object sphere [
      diffuse 0 0 0
      specular 1 1 1
      shine 120
      reflect 0.08 0.08 0.08
      transparent 0.92 0.92 0.92
      ior 1.5
    ]
  ]

  # Tinted (sea-green) glass cube, turned 35 degrees: casts a coloured shadow.
  trans [
    translate -2.3 0.63 2.3
    rotate 0 1 0 35
    scale 1.2 1.2 1.2
    object cube [
      diffuse 0 0 0
      specular 1 1 1
      shine 120
      reflect 0.06 0.06 0.06
      transparent 0.45 0.85 0.7
      ior 1.45
    ]
  ]

  # Chrome ball.
  trans [
    translate -1.4 0.7 -0.1
    scale 1.4 1.4 1.4
    object sphere [
      diffuse 0.05 0.05 0.05
      specular 1 1 1
      shine 150
      reflect 0.8 0.8 0.82
    ]
  ]

  # Red cone under the spotlight, stretched vertically (non-uniform scale).
  trans [
    translate -0.5 1.1 -1.6
    scale 1.6 2.2 1.6
    object cone [
      ambient 0.08 0.01 0.01
      diffuse 0.85 0.1 0.08
      specular 0.6 0.6 0.6
      shine 40
    ]
  ]

  # Gold cylinder lying on its side: rotate z 90 lays the axis along x.
  trans [
    translate 2.8 0.5 -0.7
    rotate 0 1 0 -30
    rotate 0 0 1 90
    scale 1 2 1
    object cylinder [
      ambient 0.09 0.07 0.02
      diffuse 0.85 0.65 0.2
      specular 0.9 0.8 0.5
      shine 50
      reflect 0.2 0.16 0.06
      gloss 25
    ]
  ]

  # Sheared blue egg: matrixRC (row by row) leans it with x += 0.35 y,
  # after a non-uniform scale; its lowest point touches the floor.
  trans [
    matrixRC 1 0.35 0 -3.7
             0 1    0  0.9
             0 0    1 -0.4
             0 0    0  1
    scale 1.3 1.8 1.3
    object sphere [
      ambient 0.01 0.03 0.08
      diffuse 0.12 0.3 0.85
      specular 0.9 0.9 0.9
      shine 80
    ]
  ]
]

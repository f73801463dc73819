# moving.sc -- animation keywords (scene-format.md §9.4) for whitted-mpi's --frames test: a sphere
# moving by (1, 0.5, 0) per unit of time and a cube turning 80 degrees per unit, over a static floor.

background [ color 0.1 0.1 0.12 ]

camera [ eye 0 2 8 focus 0 0 0 up 0 1 0 angle 45 ]

light [ type point position -4 5 4 color 0.9 0.9 0.9 ]

mastersubgraph root [
  trans [
    translate 0 -1 0
    scale 10 0.1 10
    object cube [ ambient 0.1 0.1 0.1 diffuse 0.7 0.7 0.7 ]
  ]
  trans [
    translate -1.5 0 0
    velocity 1 0.5 0
    object sphere [ ambient 0.1 0 0 diffuse 0.8 0.2 0.2 specular 0.5 0.5 0.5 shine 20 ]
  ]
  trans [
    translate 1.5 0 0
    angularrate 0 1 1 80
    object cube [ ambient 0 0 0.1 diffuse 0.2 0.3 0.8 ]
  ]
]

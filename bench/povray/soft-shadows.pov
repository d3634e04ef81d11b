// Twin of bench/scenes/soft-shadows.crt: nine balls under one 8x8 jittered area light.
// POV-Ray's area_light takes its corner at the centre: location (0,6,0), axes 2 units long.
global_settings { max_trace_level 1 assumed_gamma 1.0 ambient_light 0 }
camera { perspective location <0, 4, -9> right x*640/360 up y angle degrees(2*atan(tan(radians(20))*640/360)) look_at <0, 0.5, 0> }
// CRT's vertical fov 40 is a horizontal one of 2·atan(tan(20°)·16/9); POV-Ray's angle is horizontal.
light_source { <0, 6, 0> color rgb <1, 1, 1>
  area_light <2, 0, 0>, <0, 0, 2>, 8, 8 jitter }
background { color rgb <0.2, 0.25, 0.35> }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.8> } finish { ambient 0.1 diffuse 1 } }
#declare I = 0;
#while (I < 9)
  sphere { <(mod(I, 3) - 1) * 2.2, 0.6, (floor(I / 3) - 1) * 2.2>, 0.6
    pigment { color rgb <0.8, 0.35, 0.25> } finish { ambient 0.1 diffuse 1 } }
  #declare I = I + 1;
#end

// Twin of bench/scenes/recursion-check.crt: every surface hit adds 0.05 (ambient 0.05 under
// ambient_light 1), so the centre pixel is 13 * max_trace_level (of 255).
//   povray -D -A +W8 +H8 +FN File_Gamma=1.0 +Irecursion-check.pov +Or.png
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 adc_bailout 0 ambient_light rgb 1 }
camera { perspective location <0, 0, 0> look_at <0, 0, 1> right x up y angle 30 }
plane { z, 5 pigment { rgb 1 } finish { ambient 0.05 diffuse 0 reflection 1 } }
plane { -z, 5 pigment { rgb 1 } finish { ambient 0.05 diffuse 0 reflection 1 } }

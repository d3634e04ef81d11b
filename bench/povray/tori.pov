// POV-Ray 3.7 twin of bench/scenes/tori.crt (1,000 tori on a 40 x 25 grid), written by hand.
// Shading mapped as in box-field.pov (docs/benchmarks.md, "How the two scenes are matched").
//   povray -D -A +WT2 +W1280 +H720 +FN File_Gamma=1.0 +Itori.pov +Otori.png
#version 3.7;
global_settings {
  assumed_gamma 1.0
  max_trace_level 1        // CRT's recursiondepth 0: primary rays and shadows only
  adc_bailout 0
  ambient_light rgb <0.135, 0.135, 0.1275>   // CRT: ambient 0.15 * light colour
}
camera {
  perspective
  location <0, 30, -30>
  right x * 1280 / 720
  up y
  angle 2 * degrees(atan(tan(radians(45 / 2)) * 1280 / 720))
  look_at <0, 0, 2>
}
background { color rgb <0.2, 0.25, 0.35> }
light_source { <-20, 40, -20> color rgb <0.9, 0.9, 0.85> }
#declare Ring = texture {
  pigment { color rgb <0.8, 0.55, 0.3> }
  finish { ambient 1 diffuse 0.8 phong 0.5 phong_size 40 }
}
#declare I = 0;
#while (I < 40)
  #declare J = 0;
  #while (J < 25)
    torus { 0.45, 0.15 texture { Ring } rotate <I * 17 + J * 29, J * 11 + I * 7, 0> translate <I - 19.5, 0, J * 1.2 - 12> }
    #declare J = J + 1;
  #end
  #declare I = I + 1;
#end
plane { y, -0.7 texture { pigment { color rgb <0.6, 0.6, 0.6> } finish { ambient 1 diffuse 1 } } }

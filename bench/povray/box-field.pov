// POV-Ray 3.7 twin of scenes/box-field.crt, written by hand for bench/povray-compare.sh.
// Same geometry, lights, shadows and reflection depth as the CRT scene; the shading is mapped
// term by term (see docs/benchmarks.md, "How the two scenes are matched"). Change one, change both.
//
// Render it the way the benchmark does:
//   povray -D -A +WT2 +W1280 +H720 +FN File_Gamma=1.0 +Ibox-field.pov +Obox-field.png
#version 3.7;

global_settings {
  assumed_gamma 1.0       // CRT's gamma 1: colours are written as computed (with File_Gamma=1.0)
  max_trace_level 6       // CRT's recursiondepth 5 = the primary hit + 5 reflections = 6 POV levels
  adc_bailout 0           // CRT has no adaptive depth control: trace every level
  ambient_light rgb <0.1, 0.1, 0.088>   // CRT: sum over lights of ambient * colour (0.4 * <0.25, 0.25, 0.22>)
}

// CRT: Camera { position vec3(0, 7.5, -17) pointing vec3(0, 1.5, 3) fov 40 }, fov vertical;
// POV-Ray's angle is horizontal: 2 atan(tan(40/2) * W/H).
camera {
  perspective
  location <0, 7.5, -17>
  right x * 1280 / 720
  up y
  angle 2 * degrees(atan(tan(radians(40 / 2)) * 1280 / 720))
  look_at <0, 1.5, 3>
}

// CRT lights have no falloff unless asked; POV-Ray's do not fade unless asked either.
light_source { <-10, 12, -10> color rgb <0.45, 0.42, 0.38> }
light_source { <10, 9, -6> color rgb <0.28, 0.3, 0.38> }
light_source { <0, 14, 14> color rgb <0.3, 0.3, 0.3> }
// CRT ParallelLight { from vec3(-2, 5, -3) pointing vec3(0, 0, 0) }: POV-Ray's parallel light
// starts its shadow rays at the plane through `location`, so put the location far out along the
// same direction: every object then lies in front of it, as for CRT's light from infinity.
light_source {
  vnormalize(<-2, 5, -3>) * 10000
  color rgb <0.25, 0.25, 0.22>
  parallel
  point_at <0, 0, 0>
}

// CRT: Background { horizon rgb(0.85, 0.88, 0.95) sky rgb(0.25, 0.4, 0.75) }, mixed by the
// elevation e = asin(y) / (pi/2), clamped to [0, 1].
sky_sphere {
  pigment {
    function { asin(min(max(y, 0), 0.999999)) / (pi / 2) }
    color_map { [0 rgb <0.85, 0.88, 0.95>] [1 rgb <0.25, 0.4, 0.75>] }
  }
}

// CRT Material { color C diffuse kd specular ks shininess n reflectivity kr } ->
//   pigment C, finish { ambient 1 (times ambient_light) diffuse kd phong ks phong_size n reflection kr }
#macro CrtFinish(Kd, Ks, N, Kr)
  finish { ambient 1 diffuse Kd brilliance 1 phong Ks phong_size N specular 0 reflection { Kr } }
#end
#declare Red   = texture { pigment { rgb <0.85, 0.35, 0.3> } CrtFinish(0.7, 0.6, 60, 0.35) }
#declare Blue  = texture { pigment { rgb <0.3, 0.6, 0.85> }  CrtFinish(0.7, 0.6, 60, 0.35) }
#declare Ivory = texture { pigment { rgb <0.9, 0.85, 0.75> } CrtFinish(0.7, 0.6, 60, 0.35) }
#declare Chrome = texture { pigment { rgb <0.8, 0.8, 0.85> } CrtFinish(0.3, 0.8, 120, 0.6) }
#declare Gold   = texture { pigment { rgb <0.9, 0.7, 0.3> }  CrtFinish(0.6, 0.7, 80, 0.3) }
#declare Ground = texture { pigment { rgb <0.55, 0.55, 0.5> } CrtFinish(0.8, 0, 30, 0.15) }

// 20 rows of 25 boxes, 0.7 wide, heights from a smooth wave; tint (i + 2j) mod 3.
#declare J = 0;
#while (J < 20)
  #declare I = 0;
  #while (I < 25)
    #declare X = I - 12;
    #declare Z = J - 6;
    #declare H = 0.35 + 0.3 * (1 + sin(0.9 * I + 0.4 * J) * cos(0.5 * J - 0.3 * I));
    box {
      <X - 0.35, 0, Z - 0.35>, <X + 0.35, H, Z + 0.35>
      #switch (mod(I + 2 * J, 3))
        #case (0) texture { Red } #break
        #case (1) texture { Blue } #break
        #else texture { Ivory }
      #end
    }
    #declare I = I + 1;
  #end
  #declare J = J + 1;
#end

// A bowl: the lower half of a sphere, flat side up. The flat face belongs to the box, so it
// shows the box's texture, as in CRT.
#declare Bowl = difference {
  sphere { <0, 0, 0>, 2.2 texture { Chrome } }
  box { <-3, 0, -3>, <3, 3, 3> texture { Gold } }
}
object { Bowl translate <-6.5, 3.2, 5> }
object { Bowl translate <0, 3.8, 9> }
object { Bowl translate <6.5, 3.2, 5> }

sphere { <-3, 1.9, 1>, 0.9 texture { Chrome } }
sphere { <3.5, 1.7, 0>, 0.7 texture { Gold } }
sphere { <-9, 1.6, 9>, 0.6 texture { Chrome } }
sphere { <9, 1.6, 10>, 0.6 texture { Gold } }

plane { y, 0 texture { Ground } }

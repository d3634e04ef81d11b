package dev.crt.lang;

import static dev.crt.lang.Scripts.CAMERA;
import static dev.crt.lang.Scripts.scene;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;
import dev.crt.scene.ApertureShape;
import dev.crt.scene.Box;
import dev.crt.scene.Camera;
import dev.crt.scene.Csg;
import dev.crt.scene.CsgOperation;
import dev.crt.scene.Entity;
import dev.crt.scene.GradientBackground;
import dev.crt.scene.Material;
import dev.crt.scene.ParallelLight;
import dev.crt.scene.Plane;
import dev.crt.scene.PointLight;
import dev.crt.scene.Rgb;
import dev.crt.scene.Scene;
import dev.crt.scene.Settings;
import dev.crt.scene.SolidBackground;
import dev.crt.scene.Sphere;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Valid scripts build the right Scene. */
class ValidScriptsTest {
    private static final double EPS = 1e-12;

    /** The value of a top-level expression, read back through a sphere's radius. */
    private static double number(String expression) {
        Scene s = scene(CAMERA + "x = " + expression + "\nScene { Sphere { radius -> x } }\n");
        return ((Sphere) s.entities().get(0)).radius();
    }

    private static void assertPoint(Vec3 actual, double x, double y, double z) {
        assertThat(actual.x()).isCloseTo(x, within(1e-9));
        assertThat(actual.y()).isCloseTo(y, within(1e-9));
        assertThat(actual.z()).isCloseTo(z, within(1e-9));
    }

    @Test
    void defaultsOfEveryObject() {
        Scene s = scene("Settings { camera -> Camera { position -> vec3(0, 0, -10) pointing -> vec3(0, 0, 0) } }\n"
                + "Scene { Sphere { } Box { cornerA -> vec3(1, 2, 3) cornerB -> vec3(0, 0, 0) } Plane { normal -> vec3(0, 2, 0) } }\n");
        Settings settings = s.settings();
        assertThat(settings.camera()).usingRecursiveComparison().ignoringFields("span")
                .isEqualTo(new Camera(new Vec3(0, 0, -10), Vec3.ZERO, 60, 0, 0, 10, ApertureShape.CIRCLE, null));
        assertThat(settings.background()).isEqualTo(new SolidBackground(Rgb.BLACK));
        assertThat(List.of(settings.supersampling(), settings.dofSamples(), settings.recursionDepth(), settings.width(),
                settings.height())).containsExactly(1, 1, 5, 800, 600);
        assertThat(settings.gamma()).isEqualTo(1);
        Sphere sphere = (Sphere) s.entities().get(0);
        assertThat(sphere.center()).isEqualTo(Vec3.ZERO);
        assertThat(sphere.radius()).isEqualTo(1);
        assertThat(sphere.material()).isEqualTo(Material.DEFAULT);
        assertThat(sphere.transform()).isEqualTo(Transform.IDENTITY);
        Box box = (Box) s.entities().get(1);
        assertThat(box.min()).isEqualTo(Vec3.ZERO);
        assertThat(box.max()).isEqualTo(new Vec3(1, 2, 3));
        Plane plane = (Plane) s.entities().get(2);
        assertThat(plane.normal()).isEqualTo(new Vec3(0, 1, 0));
        assertThat(plane.position()).isEqualTo(Vec3.ZERO);
    }

    @Test
    void everyAttributeIsRead() {
        Scene s = scene("""
                Settings {
                  title -> "T" author -> "A" date -> "2015" notes -> "n \\"q\\" \\\\"
                  camera -> Camera { position -> vec3(1, 2, 3) pointing -> vec3(0, 0, 1) fov -> 45 roll -> 10
                                     aperture -> 20 focaldistance -> 4 apertureshape -> "hexagon" }
                  lights -> [PointLight { origin -> vec3(0, 5, 0) color -> rgb(1, 0.5, 0) falloff -> 2 ambient -> 0.1 },
                             ParallelLight { from -> vec3(0, 1, 0) pointing -> vec3(0, 0, 0) color -> rgb(0.2, 0.2, 0.2) ambient -> 0.3 }]
                  background -> Background { horizon -> rgb(1, 1, 1) sky -> rgb(0, 0, 1) }
                  supersampling -> 3 dofsamples -> 4 recursiondepth -> 0 gamma -> 2.2 width -> 320 height -> 200
                }
                Scene {
                  Sphere { center -> vec3(1, 2, 3) radius -> 0
                           material -> Material { color -> rgb(1, 0, 0) diffuse -> 0.7 specular -> 0.3 shininess -> 50
                                                  reflectivity -> 0.5 transparency -> 0.25 ior -> 1.5 emission -> rgb(0.1, 0.2, 0.3) } }
                  Plane { normal -> vec3(0, 0, -3) position -> vec3(0, -1, 0) }
                }
                """);
        Settings st = s.settings();
        assertThat(List.of(st.title(), st.author(), st.date(), st.notes())).containsExactly("T", "A", "2015", "n \"q\" \\");
        Camera c = st.camera();
        assertThat(c.position()).isEqualTo(new Vec3(1, 2, 3));
        assertThat(List.of(c.fov(), c.roll(), c.aperture(), c.focalDistance())).containsExactly(45.0, 10.0, 20.0, 4.0);
        assertThat(c.apertureShape()).isEqualTo(ApertureShape.HEXAGON);
        assertThat(c.span().line()).isEqualTo(3);
        PointLight p = (PointLight) st.lights().get(0);
        assertThat(p.origin()).isEqualTo(new Vec3(0, 5, 0));
        assertThat(p.color()).isEqualTo(new Rgb(1, 0.5, 0));
        assertThat(List.of(p.falloff(), p.ambient())).containsExactly(2.0, 0.1);
        ParallelLight q = (ParallelLight) st.lights().get(1);
        assertThat(q.towardsLight()).isEqualTo(new Vec3(0, 1, 0));
        assertThat(q.ambient()).isEqualTo(0.3);
        assertThat(st.background()).isEqualTo(new GradientBackground(Rgb.WHITE, new Rgb(0, 0, 1)));
        assertThat(List.of(st.supersampling(), st.dofSamples(), st.recursionDepth(), st.width(), st.height()))
                .containsExactly(3, 4, 0, 320, 200);
        assertThat(st.gamma()).isEqualTo(2.2);
        Sphere sphere = (Sphere) s.entities().get(0);
        assertThat(sphere.radius()).isZero();
        assertThat(sphere.material()).isEqualTo(new Material(new Rgb(1, 0, 0), 0.7, 0.3, 50, 0.5, 0.25, 1.5, new Rgb(0.1, 0.2, 0.3)));
        Plane plane = (Plane) s.entities().get(1);
        assertThat(plane.normal()).isEqualTo(new Vec3(0, 0, -1));
    }

    @Test
    void laterSettingsOverrideEarlierOnesAndScenesAccumulate() {
        Scene s = scene(CAMERA + """
                Settings { width -> 100 height -> 50 }
                Scene { Sphere { radius -> 1 } }
                Settings { width -> 200 background -> Background { color -> rgb(0.5, 0.5, 0.5) } }
                Scene { Sphere { radius -> 2 } Sphere { radius -> 3 } }
                """);
        assertThat(s.settings().width()).isEqualTo(200);
        assertThat(s.settings().height()).isEqualTo(50);
        assertThat(s.settings().background()).isEqualTo(new SolidBackground(Rgb.GREY));
        assertThat(s.entities()).extracting(e -> ((Sphere) e).radius()).containsExactly(1.0, 2.0, 3.0);
    }

    @Test
    void entitiesCarryTheirSpan() {
        Scene s = scene(CAMERA + "Scene {\n  Sphere { radius -> 1 }\n}\n");
        Entity e = s.entities().get(0);
        assertThat(e.span().line()).isEqualTo(3);
        assertThat(e.span().column()).isEqualTo(3);
        assertThat(e.span().end() - e.span().start()).isEqualTo("Sphere { radius -> 1 }".length());
    }

    @Test
    void modifiersApplyInOrderAboutTheOrigin() {
        Scene s = scene(CAMERA + """
                ball = Sphere { }
                Scene {
                  ball <translate vec3(1, 0, 0), rotate vec3(0, 90, 0)>
                  ball <rotate vec3(0, 90, 0), translate vec3(1, 0, 0)>
                  ball <scale vec3(2, 3, 4), translate vec3(0, 1, 0)>
                  ball <scale 2>
                  ball
                }
                """);
        List<Entity> es = s.entities();
        // rotate vec3(0, 90, 0) takes +x to -z.
        assertPoint(es.get(0).transform().applyToPoint(Vec3.ZERO), 0, 0, -1);
        assertPoint(es.get(1).transform().applyToPoint(Vec3.ZERO), 1, 0, 0);
        assertPoint(es.get(2).transform().applyToPoint(new Vec3(1, 1, 1)), 2, 4, 4);
        assertPoint(es.get(3).transform().applyToPoint(new Vec3(1, 1, 1)), 2, 2, 2);
        assertThat(es.get(4).transform()).as("values are immutable: ball did not move").isEqualTo(Transform.IDENTITY);
    }

    @Test
    void modifiersOnAMacroResultApplyToEachEntity() {
        Scene s = scene(CAMERA + """
                pair = Macro () { Sphere { } Sphere { center -> vec3(0, 1, 0) } }
                Scene { pair() <translate vec3(5, 0, 0)> }
                """);
        assertThat(s.entities()).hasSize(2);
        assertThat(s.entities()).allSatisfy(e -> assertPoint(e.transform().applyToPoint(Vec3.ZERO), 5, 0, 0));
    }

    @Test
    void csgBuildsTrees() {
        Scene s = scene(CAMERA + """
                a = Sphere { } b = Sphere { radius -> 0.5 } c = Box { cornerA -> vec3(0,0,0) cornerB -> vec3(1,1,1) } d = Sphere { radius -> 2 }
                moved = (a - b) <translate vec3(0, 1, 0)>
                Scene {
                  a ^ b ^ c ^ d
                  d - a - b
                  a + b
                  moved
                }
                """);
        Csg chained = (Csg) s.entities().get(0);
        assertThat(chained.operation()).isEqualTo(CsgOperation.INTERSECTION);
        assertThat(chained.right()).isInstanceOf(Sphere.class);
        assertThat(((Sphere) chained.right()).radius()).isEqualTo(2);
        Csg inner = (Csg) ((Csg) chained.left()).left();
        assertThat(((Sphere) inner.left()).radius()).isEqualTo(1);
        assertThat(((Sphere) inner.right()).radius()).isEqualTo(0.5);
        Csg bowl = (Csg) s.entities().get(1);
        assertThat(bowl.operation()).isEqualTo(CsgOperation.DIFFERENCE);
        assertThat(((Csg) bowl.left()).operation()).isEqualTo(CsgOperation.DIFFERENCE);
        assertThat(((Sphere) ((Csg) bowl.left()).left()).radius()).isEqualTo(2);
        assertThat(((Csg) s.entities().get(2)).operation()).isEqualTo(CsgOperation.UNION);
        Csg moved = (Csg) s.entities().get(3);
        assertPoint(moved.transform().applyToPoint(Vec3.ZERO), 0, 1, 0);
        assertThat(moved.left().transform()).isEqualTo(Transform.IDENTITY);
        assertThat(moved.span().line()).isEqualTo(3);
    }

    @Test
    void macrosLoopsAndConditions() {
        Scene s = scene(CAMERA + """
                ball = Sphere { radius -> 0.25 }
                row = Macro (n, y) {
                  i = 0
                  while (i < n) {
                    if (i % 2 == 0) { ball <translate vec3(i, y, 0)> }
                    else if (i == 3) { ball <translate vec3(i, y, 1)> }
                    else { ball <translate vec3(i, y, 2)> }
                    i = i + 1
                  }
                  "strings and numbers contribute nothing"
                  42
                }
                empty = Macro () { x = 1 }
                both = row(5, 7)
                Scene { both empty() row(1, 0) }
                """);
        assertThat(s.entities()).hasSize(6);
        assertThat(s.entities()).extracting(e -> e.transform().applyToPoint(Vec3.ZERO)).containsExactly(
                new Vec3(0, 7, 0), new Vec3(1, 7, 2), new Vec3(2, 7, 0), new Vec3(3, 7, 1), new Vec3(4, 7, 0), Vec3.ZERO);
    }

    @Test
    void macrosReadGlobalsAndAssignLocals() {
        Scene s = scene(CAMERA + """
                r = 2
                m = Macro () { r = 5 Sphere { radius -> r } }
                Scene { m() Sphere { radius -> r } }
                """);
        assertThat(s.entities()).extracting(e -> ((Sphere) e).radius()).containsExactly(5.0, 2.0);
    }

    @Test
    void recursionUpTo256CallsIsFine() {
        Scene s = scene(CAMERA + "chain = Macro (n) { if (n > 0) { Sphere { radius -> n } chain(n - 1) } }\nScene { chain(250) }\n");
        assertThat(s.entities()).hasSize(250);
    }

    @Test
    void numbersAndOperators() {
        assertThat(number("162./255")).isCloseTo(162.0 / 255, within(EPS));
        assertThat(number(".5")).isEqualTo(0.5);
        assertThat(number("1e-3")).isEqualTo(0.001);
        assertThat(number("2.5E4")).isEqualTo(25000);
        assertThat(number("1/2")).isEqualTo(0.5);
        assertThat(number("7 % 4")).isEqualTo(3);
        assertThat(number("1 + 2 * 3")).isEqualTo(7);
        assertThat(number("(1 + 2) * 3")).isEqualTo(9);
        assertThat(number("-2 * -3")).isEqualTo(6);
        assertThat(number("10 - 4 - 3")).isEqualTo(3);
        assertThat(number("1 < 2 && 2 <= 2 && !(3 > 4) || false ? 8 : 9")).isEqualTo(8);
        assertThat(number("false ? 1 : true ? 2 : 3")).isEqualTo(2);
        assertThat(number("1 == 1.0 ? 1 : 0")).isEqualTo(1);
        assertThat(number("\"a\" != \"b\" ? 1 : 0")).isEqualTo(1);
        assertThat(number("vec3(1,2,3) == vec3(1,2,3) ? 1 : 0")).isEqualTo(1);
        assertThat(number("t")).isZero();
        assertThat(number("pi")).isEqualTo(Math.PI);
        assertThat(number("(a = 4) + a")).isEqualTo(8);
    }

    @Test
    void vectorsColoursAndLists() {
        assertThat(number("(vec3(1,2,3) + vec3(1,1,1) * 2 - 2 * vec3(0,0,1) - -vec3(1,0,0))[0]")).isEqualTo(4);
        assertThat(number("(vec3(2,4,6) / 2)[2]")).isEqualTo(3);
        assertThat(number("(rgb(0.5,1,1) * rgb(0.5,0.5,1))[0]")).isEqualTo(0.25);
        assertThat(number("(rgb(0.5,0,0) + rgb(0.25,0,0))[0] * 4")).isEqualTo(3);
        assertThat(number("(rgb(1,1,1) * 0.5)[1]")).isEqualTo(0.5);
        assertThat(number("len([1, \"two\", vec3(0,0,0)] + [[4]])")).isEqualTo(4);
        assertThat(number("[1, [2, 3]][1][0]")).isEqualTo(2);
        assertThat(number("len([])")).isZero();
    }

    @Test
    void builtIns() {
        assertThat(number("sin(pi / 2) + cos(0) + tan(0)")).isCloseTo(2, within(EPS));
        assertThat(number("asin(1) + acos(1) + atan(0) + atan2(1, 1)")).isCloseTo(Math.PI / 2 + Math.PI / 4, within(EPS));
        assertThat(number("sqrt(16) + pow(2, 10) + exp(0) + log(1)")).isEqualTo(1029);
        assertThat(number("abs(-3) + floor(2.7) + ceil(2.1) + round(2.5)")).isEqualTo(11);
        assertThat(number("min(3, 4) + max(3, 4) + clamp(9, 0, 2)")).isEqualTo(9);
        assertThat(number("mix(2, 4, 0.5) + mix(vec3(0,0,0), vec3(2,2,2), 0.5)[1]")).isEqualTo(4);
        assertThat(number("dot(vec3(1,2,3), vec3(1,1,1)) + cross(vec3(1,0,0), vec3(0,1,0))[2]")).isEqualTo(7);
        assertThat(number("length(vec3(3,4,0)) + normalize(vec3(0,5,0))[1]")).isEqualTo(6);
        assertThat(number("degrees(radians(90))")).isCloseTo(90, within(EPS));
        double r = number("rand(2, 3)");
        assertThat(r).isBetween(2.0, 3.0);
        assertThat(number("rand(2, 3)")).as("deterministic").isEqualTo(r);
    }

    @Test
    void integerResultsStayIntegers() {
        Scene s = scene(CAMERA + "Settings { width -> 3 * 100 + 7 % 4 height -> floor(200.5) supersampling -> abs(-2) }\nScene { }\n");
        assertThat(s.settings().width()).isEqualTo(303);
        assertThat(s.settings().height()).isEqualTo(200);
        assertThat(s.settings().supersampling()).isEqualTo(2);
        assertThat(Scripts.error("Settings { width -> 600 / 2 }\n").message())
                .isEqualTo("attribute 'width' of Settings expects an integer, got the float 300.0");
    }

    @Test
    void whitespaceCommentsAndLineContinuation() {
        Scene s = scene(CAMERA + """
                b0 = Sphere { } b1 = Sphere { radius -> 2 } b2 = Sphere { radius -> 3 } -- three statements on one line
                box = Box { cornerA -> vec3(-1,-1,-1) cornerB -> vec3(1,1,1) }
                a = 1
                - 3 -- continues: a = 1 - 3
                Scene { b0 b1 b2
                  box - b0
                  b1
                  box
                  + b2
                }
                """);
        assertThat(s.entities()).hasSize(6);
        assertThat(s.entities().get(3)).isInstanceOf(Csg.class);
        assertThat(s.entities().get(4)).isInstanceOf(Sphere.class);
        assertThat(((Csg) s.entities().get(5)).operation()).isEqualTo(CsgOperation.UNION);
        assertThat(number("-(1\n- 3)")).as("a line starting with - continues").isEqualTo(2);
        assertThat(Scripts.compile(CAMERA + "s = Sphere { }\nx = 1\n(s)\n").diagnostics().get(0).message())
                .as("a line starting with ( continues: 1(s) is a call").isEqualTo("cannot call number: only macros and functions take arguments (the '(' at the start of line 4"
                        + " continues the expression of the line before it: a newline does not end a statement)");
    }

    @Test
    void crlfBomAndTabsCountLikeCharacters() {
        CompileResult r = Scripts.compile("\uFEFFa = 1\r\n\tb = \"x\" * 2\r\n");
        Diagnostic d = r.diagnostics().get(0);
        assertThat(d.span().line()).isEqualTo(2);
        assertThat(d.span().column()).isEqualTo(6);
    }

    @Test
    void originalCrtStyleScript() {
        StringBuilder script = new StringBuilder(CAMERA);
        script.append("red = Material { color -> rgb(162./255, 0, .5) }\n");
        for (int i = 0; i < 30; i++) {
            script.append("b").append(i).append(" = Box {\n  cornerA -> vec3(").append(i).append(", 0, 0)\n  cornerB -> vec3(")
                    .append(i).append(".5, 1, 1)\n  material -> red\n}\n");
        }
        script.append("""
                d = Sphere { radius -> 2 }
                m1 = Sphere { radius -> 1.8 }
                m2 = Box { cornerA -> vec3(-3, 0, -3) cornerB -> vec3(3, 3, 3) }
                bowl = d - m1 - m2
                a = Sphere { } b = Sphere { center -> vec3(.5, 0, 0) } c = Sphere { center -> vec3(0, .5, 0) } e = Sphere { center -> vec3(0, 0, .5) }
                lens = a ^ b ^ c ^ e
                Scene {
                """);
        for (int i = 0; i < 30; i++) script.append(" b").append(i);
        script.append("\n  bowl\n  lens <rotate vec3(0, 45, 0)>\n}\n");
        Scene s = scene(script.toString());
        assertThat(s.entities()).hasSize(32);
        Box b7 = (Box) s.entities().get(7);
        assertThat(b7.min()).isEqualTo(new Vec3(7, 0, 0));
        assertThat(b7.max()).isEqualTo(new Vec3(7.5, 1, 1));
        assertThat(b7.material().color().r()).isCloseTo(162.0 / 255, within(EPS));
        Csg bowl = (Csg) s.entities().get(30);
        assertThat(((Csg) bowl.left()).right()).isInstanceOf(Sphere.class);
        Csg lens = (Csg) s.entities().get(31);
        assertThat(lens.operation()).isEqualTo(CsgOperation.INTERSECTION);
    }

    @Test
    void timeComesFromTheOptions() {
        CompileResult r = CrtCompiler.compile(Source.of("t.crt", CAMERA + "Scene { Sphere { radius -> t / 10 } }\n"),
                CompileOptions.DEFAULT.withTime(5));
        assertThat(((Sphere) r.scene().entities().get(0)).radius()).isEqualTo(0.5);
    }

    @Test
    void aHundredThousandObjectsFromLoops() {
        Scene s = scene(CompileSpeed.hundredThousandObjects());
        assertThat(s.entities()).hasSize(317 * 317);
        assertPoint(s.entities().get(317 * 317 - 1).transform().applyToPoint(Vec3.ZERO), 316 * 0.25, 316 * 0.25, 0);
    }

    @Test
    void expressionsInLoopsMeanWhatTheyMeanOnce() {
        String body = "a = [1, 2][1] * -3 + (true && !false ? 4 % 3 : 0) + len([1]) + sqrt(4) / 2 + pow(2, 2)\n"
                + "b = vec3(1, 2, 3) == vec3(0,0,0) || 2 >= 1 ? 1 : 0\n";
        Scene once = scene(CAMERA + body + "Scene { Sphere { radius -> a + b } }\n");
        Scene looped = scene(CAMERA + "i = 0\nwhile (i < 3) {\n" + body + "i = i + 1\n}\nScene { Sphere { radius -> a + b } }\n");
        assertThat(((Sphere) once.entities().get(0)).radius()).isEqualTo(2);
        assertThat(((Sphere) looped.entities().get(0)).radius()).isEqualTo(2);
    }

    @Test
    void definedButUnplacedObjectsCostNothing() {
        Scene s = scene(CAMERA + "a = Sphere { }\nScene { }\n");
        assertThat(s.entities()).isEmpty();
    }
}

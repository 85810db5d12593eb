package org.miron.dds.types;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/** Reading definitions: what each grammar accepts, and every refusal at its file, line and column. */
public class DefinitionsTest {
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    private static String msgError(String text) {
        try {
            MsgParser.parse("Bad.msg", "pkg", "Bad", text);
        } catch (DefinitionException e) {
            return e.format();
        }
        throw new AssertionError("accepted: " + text);
    }

    private static String idlError(String text) {
        try {
            IdlParser.parse("Bad.idl", text);
        } catch (DefinitionException e) {
            return e.format();
        }
        throw new AssertionError("accepted: " + text);
    }

    @Test
    public void badMsgLinesAreRefusedAtTheirToken() {
        assertEquals("Bad.msg:2:3: error [dds-types]: unknown type flaot32 (not a primitive: bool, byte, char, float32, float64,"
                + " int8 ... uint64, string, wstring; a message type is CamelCase); did you mean float32?",
                msgError("# comment\n  flaot32 x\n"));
        assertTrue(msgError("uint8 x 300"), msgError("uint8 x 300").startsWith("Bad.msg:1:9: error [dds-types]: bad default of x: 300 is out of the range of a uint8"));
        assertTrue(msgError("int32 ok\nint32 X=abc").startsWith("Bad.msg:2:9: error [dds-types]: bad value of constant X"));
        assertTrue(msgError("float64").startsWith("Bad.msg:1:8: error [dds-types]: a field needs a name"));
        assertTrue(msgError("int32 Bad_Name").startsWith("Bad.msg:1:7: error [dds-types]: a field name is lower case"));
        assertTrue(msgError("int32 a\nint32 a").startsWith("Bad.msg:2:7: error [dds-types]: field a is defined twice (first at line 1)"));
        assertTrue(msgError("int32[<=2] a [1, 2, 3]").contains("at most 2 elements"));
        assertTrue(msgError("float64<=3 a").startsWith("Bad.msg:1:1: error [dds-types]: only strings have a bound"));
        assertTrue(msgError("string<=3 a \"long\"").contains("longer than the bound 3"));
        assertTrue(msgError("Point[] p [1]").contains("cannot have a default"));
        assertTrue(msgError("int32 lower=1").contains("a constant name is upper case"));
        assertTrue(msgError("geometry_msgs/point p").startsWith("Bad.msg:1:1: error [dds-types]: not a message type"));
    }

    @Test
    public void aMsgReadsConstantsDefaultsArraysAndBareNames() throws Exception {
        MsgType t = MsgParser.parse("A.msg", "pkg", "A", """
                uint8 KIND=3   # a constant
                string NOTE="a # b"
                string<=4 name "ab"  # a default, then a comment
                float32[2] xy [0.5, 1.5]
                Other[] others
                Header header
                time t
                """);
        assertEquals(3, t.constants().get("KIND").asInt());
        assertEquals("a # b", t.constants().get("NOTE").asText());
        assertEquals(List.of("name", "xy", "others", "header", "t"), t.fields().stream().map(MsgField::name).toList());
        assertEquals("ab", t.field("name").defaultValue().asText());
        assertEquals(4, t.field("name").type().stringBound());
        assertEquals(FieldType.Array.FIXED, t.field("xy").type().array());
        assertEquals("pkg/Other", t.field("others").type().message());
        assertEquals("std_msgs/Header", t.field("header").type().message());
        assertEquals("builtin_interfaces/Time", t.field("t").type().message());
        assertEquals("pkg::msg::dds_::A_", t.ddsName());
    }

    @Test
    public void badIdlIsRefusedAtItsToken() {
        String head = "module pkg {\n  module msg {\n    struct S {\n";
        assertEquals("Bad.idl:4:7: error [dds-types]: unknown type flaot (an IDL primitive such as double, int32, boolean, string,"
                + " or pkg::msg::Name)", idlError(head + "      flaot x;\n    };\n  };\n};\n"));
        assertTrue(idlError(head + "      double x\n    };\n  };\n};\n").startsWith("Bad.idl:5:5: error [dds-types]: expected ;, found }"));
        assertTrue(idlError(head + "      @default (value=300)\n      uint8 x;\n    };\n  };\n};\n").startsWith("Bad.idl:5:7: error [dds-types]: bad default of x"));
        assertTrue(idlError("struct S { double x; };").startsWith("Bad.idl:1:8: error [dds-types]: a message struct belongs in module pkg"));
        assertTrue(idlError(head + "      double x;\n").contains("unexpected end of file"));
        assertTrue(idlError("union U switch (long) { case 1: long a; };").startsWith("Bad.idl:1:1: error [dds-types]: expected module, struct"));
    }

    @Test
    public void anIdlReadsAsRosidlWritesIt() throws Exception {
        List<MsgType> l = IdlParser.parse("S.idl", """
                // generated
                #include "std_msgs/msg/Header.idl"
                module pkg {
                  module msg {
                    typedef double double__9[9];
                    module S_Constants {
                      const int32 MINUS = -5;
                      const string WORD = "w";
                    };
                    /* a block comment */
                    @verbatim (language="comment", text="doc")
                    struct S {
                      std_msgs::msg::Header header;
                      @default (value=TRUE)
                      boolean on;
                      sequence<int32, 3> few;
                      sequence<pkg::msg::T> many;
                      string<10> name;
                      double__9 covariance;
                      unsigned long long big;
                      @default (value="(1, 2)")
                      sequence<uint8> bytes;
                      float xy[2];
                    };
                  };
                };
                """);
        MsgType s = l.get(0);
        assertEquals("pkg/S", s.fullName());
        assertEquals(-5, s.constants().get("MINUS").asInt());
        assertEquals("w", s.constants().get("WORD").asText());
        assertEquals("std_msgs/Header", s.field("header").type().message());
        assertTrue(s.field("on").defaultValue().asBoolean());
        assertEquals("int32[<=3]", s.field("few").type().toString());
        assertEquals("pkg/T[]", s.field("many").type().toString());
        assertEquals("string<=10", s.field("name").type().toString());
        assertEquals("float64[9]", s.field("covariance").type().toString());
        assertEquals(Primitive.UINT64, s.field("big").type().primitive());
        assertEquals("[1,2]", s.field("bytes").defaultValue().toString());
        assertEquals("float32[2]", s.field("xy").type().toString());
    }

    private Path pkg(String folder, String xmlName, String file, String text) throws Exception {
        Path dir = tmp.getRoot().toPath().resolve(folder);
        Files.createDirectories(dir.resolve("msg"));
        if (xmlName != null) {
            Files.writeString(dir.resolve("package.xml"), "<package format=\"3\"><name>" + xmlName + "</name></package>");
        }
        Files.writeString(dir.resolve("msg").resolve(file), text);
        return dir;
    }

    @Test
    public void packagesAreNamedByPackageXmlElseTheFolder() throws Exception {
        Path a = pkg("some_folder", "robot_msgs", "Battery.msg", "float32 level\nDock dock\n");
        Files.writeString(a.resolve("msg/Dock.msg"), "string id\n");
        Path b = pkg("other_msgs", null, "Uses.msg", "robot_msgs/Battery battery\nstd_msgs/Header header\n");
        TypeRegistry r = MessagePackages.load(List.of(a, b), t -> false, w -> fail(w));
        assertTrue(r.isLoaded("robot_msgs/Battery"));
        assertTrue(r.isLoaded("other_msgs/Uses"));
        assertEquals("robot_msgs/Dock", r.get("robot_msgs/Battery").field("dock").type().message());
        assertEquals("", r.template(r.get("other_msgs/Uses")).path("battery").path("dock").path("id").asText());
        assertEquals(0, r.template(r.get("other_msgs/Uses")).path("header").path("stamp").path("sec").asInt());
    }

    @Test
    public void anUnknownNestedTypeIsRefusedAtItsLine() throws Exception {
        Path a = pkg("robot_msgs", null, "Battery.msg", "float32 level\n\n  Charger charger\n");
        try {
            MessagePackages.load(List.of(a), t -> false, w -> { });
            fail("loaded");
        } catch (DefinitionException e) {
            assertTrue(e.format(), e.format().startsWith(a.resolve("msg/Battery.msg") + ":3:3: error [dds-types]: unknown message type robot_msgs/Charger"));
        }
        Path c = pkg("loop_msgs", null, "A.msg", "B b\n");
        Files.writeString(c.resolve("msg/B.msg"), "A a\n");
        try {
            MessagePackages.load(List.of(c), t -> false, w -> { });
            fail("loaded");
        } catch (DefinitionException e) {
            assertTrue(e.format(), e.format().contains("contains itself"));
        }
    }

    @Test
    public void aLoadedPackageThatRedefinesAShippedTypeWinsWithAWarning() throws Exception {
        Path s = pkg("std_msgs", null, "String.msg", "string data\nuint32 extra\n");
        List<String> warnings = new ArrayList<>();
        TypeRegistry r = MessagePackages.load(List.of(s), t -> t.equals("std_msgs/String"), warnings::add);
        assertEquals(List.of(s.resolve("msg/String.msg") + ":1:1: warning [dds-types]: std_msgs/String redefines a type the bridge"
                + " ships; this definition is used"), warnings);
        assertTrue(r.isLoaded("std_msgs/String"));
        assertTrue(r.template(r.get("std_msgs/String")).has("extra"));
        assertFalse(TypeRegistry.NONE.isLoaded("std_msgs/String"));
        assertNull(TypeRegistry.NONE.get("nav2_msgs/SpeedLimit"));
    }

    @Test
    public void constantsAreNotFields() throws Exception {
        TypeRegistry r = MessagePackages.load(List.of(CdrOracleTest.fixture("my_robot_msgs")), t -> false, w -> { });
        MsgType p = r.get("my_robot_msgs/PowerStatus");
        assertEquals(2, p.constants().get("STATUS_CHARGING").asInt());
        assertEquals("bms-1 # not a comment", p.constants().get("DRIVER").asText());
        assertFalse(r.template(p).has("STATUS_CHARGING"));
        assertEquals("acme", r.get("my_robot_msgs/ChargerInfo").constants().get("VENDOR").asText());
    }
}

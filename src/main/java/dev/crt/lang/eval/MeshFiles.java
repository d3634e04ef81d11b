package dev.crt.lang.eval;

import dev.crt.lang.eval.MeshBuilder.MeshProblem;
import dev.crt.scene.MeshData;
import java.io.BufferedReader;
import java.io.IOException;
import java.nio.BufferUnderflowException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Reads the mesh files of crt-language.md section 13: Wavefront OBJ (v, vt, vn and f with
 * polygons fanned; everything else ignored), RAW (nine numbers a triangle) and PLY (ASCII and
 * binary little-endian; vertex and face elements). Every problem is a {@link MeshProblem} whose
 * sentence names the line or the element at fault; nothing here throws anything else on bad input.
 */
final class MeshFiles {
    /** Files above this size are refused before reading (the whole file is read into memory). */
    static final long MAX_BYTES = 1L << 30;

    private MeshFiles() {}

    static MeshData read(Path file) throws MeshProblem {
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        try {
            long size = Files.size(file);
            if (size > MAX_BYTES) {
                throw new MeshProblem("the file is " + size / (1 << 20) + " MiB; meshes up to " + (MAX_BYTES >> 20) + " MiB are read");
            }
            MeshBuilder b = new MeshBuilder();
            if (name.endsWith(".obj")) obj(file, b);
            else if (name.endsWith(".raw")) raw(file, b);
            else if (name.endsWith(".ply")) ply(file, b);
            else throw new MeshProblem("a mesh file must end in .obj, .raw or .ply");
            return b.finish(file.toString());
        } catch (IOException e) {
            throw new MeshProblem("cannot read it: " + e.getMessage());
        } catch (OutOfMemoryError e) {
            throw new MeshProblem("it is too large for the memory CRT may use");
        }
    }

    private static void obj(Path file, MeshBuilder b) throws IOException, MeshProblem {
        try (BufferedReader in = Files.newBufferedReader(file, StandardCharsets.ISO_8859_1)) {
            String line;
            int number = 0;
            int[] corners = new int[48];
            Place where = new Place("line");
            while ((line = in.readLine()) != null) {
                where.index = ++number;
                String[] w = line.trim().split("\\s+");
                if (w.length == 0 || w[0].isEmpty() || w[0].startsWith("#")) continue;
                switch (w[0]) {
                    case "v" -> b.position(num(w, 1, where), num(w, 2, where), num(w, 3, where), where);
                    case "vt" -> b.uv(num(w, 1, where), w.length > 2 ? num(w, 2, where) : 0, where);
                    case "vn" -> b.normal(num(w, 1, where), num(w, 2, where), num(w, 3, where), where);
                    case "f" -> {
                        int n = w.length - 1;
                        if (3 * n > corners.length) corners = new int[3 * n];
                        for (int i = 0; i < n; i++) {
                            String[] parts = w[i + 1].split("/", -1);
                            corners[3 * i] = index(parts[0], b.positions(), where);
                            corners[3 * i + 1] = parts.length > 1 && !parts[1].isEmpty() ? index(parts[1], b.uvs(), where) : -1;
                            corners[3 * i + 2] = parts.length > 2 && !parts[2].isEmpty() ? index(parts[2], b.normals(), where) : -1;
                        }
                        b.polygon(corners, n, where);
                    }
                    default -> { }
                }
            }
        }
    }

    /** An OBJ index: 1-based, or negative counting back from the last one read; returned 0-based. */
    private static int index(String text, int count, Object where) throws MeshProblem {
        int i;
        try {
            i = Integer.parseInt(text);
        } catch (NumberFormatException e) {
            throw new MeshProblem(where + "'" + text + "' is not a vertex index");
        }
        if (i == 0) throw new MeshProblem(where + "index 0: OBJ indices start at 1");
        return i > 0 ? i - 1 : count + i;
    }

    private static double num(String[] w, int i, Object where) throws MeshProblem {
        if (i >= w.length) throw new MeshProblem(where + "too few numbers after '" + w[0] + "'");
        return parse(w[i], where);
    }

    private static double parse(String text, Object where) throws MeshProblem {
        try {
            return Double.parseDouble(text);
        } catch (NumberFormatException e) {
            throw new MeshProblem(where + "'" + text + "' is not a number");
        }
    }

    private static void raw(Path file, MeshBuilder b) throws IOException, MeshProblem {
        List<Double> values = new ArrayList<>();
        int[] corners = {0, -1, -1, 1, -1, -1, 2, -1, -1};
        try (BufferedReader in = Files.newBufferedReader(file, StandardCharsets.ISO_8859_1)) {
            String line;
            int number = 0;
            Place where = new Place("line");
            while ((line = in.readLine()) != null) {
                where.index = ++number;
                for (String w : line.trim().split("\\s+")) {
                    if (w.isEmpty()) continue;
                    values.add(parse(w, where));
                    if (values.size() == 9) {
                        int base = b.positions();
                        for (int k = 0; k < 3; k++) b.position(values.get(3 * k), values.get(3 * k + 1), values.get(3 * k + 2), where);
                        for (int k = 0; k < 3; k++) corners[3 * k] = base + k;
                        b.polygon(corners, 3, where);
                        values.clear();
                    }
                }
            }
            if (!values.isEmpty()) {
                throw new MeshProblem("the file ends in the middle of a triangle: " + values.size() + " numbers left over (RAW has 9 per triangle)");
            }
        }
    }

    /** One PLY property: its name, its type, and for a list the type of its length. */
    private record Property(String name, String type, String countType) {}

    private record Element(String name, long count, List<Property> properties) {}

    private static void ply(Path file, MeshBuilder b) throws IOException, MeshProblem {
        byte[] bytes = Files.readAllBytes(file);
        // The header is ASCII lines up to "end_header".
        int pos = 0;
        List<String> header = new ArrayList<>();
        while (true) {
            int end = pos;
            while (end < bytes.length && bytes[end] != '\n') end++;
            if (end >= bytes.length) throw new MeshProblem("the PLY header has no end_header line");
            String line = new String(bytes, pos, end - pos, StandardCharsets.ISO_8859_1).trim();
            pos = end + 1;
            header.add(line);
            if (line.equals("end_header")) break;
        }
        if (!header.get(0).equals("ply")) throw new MeshProblem("a PLY file starts with the line 'ply'");
        String format = null;
        List<Element> elements = new ArrayList<>();
        for (int i = 1; i < header.size(); i++) {
            String[] w = header.get(i).split("\\s+");
            String where = "header line " + (i + 1) + ": ";
            switch (w[0]) {
                case "format" -> format = w.length > 1 ? w[1] : "";
                case "element" -> {
                    if (w.length < 3) throw new MeshProblem(where + "an element needs a name and a count");
                    long count;
                    try {
                        count = Long.parseLong(w[2]);
                    } catch (NumberFormatException e) {
                        throw new MeshProblem(where + "'" + w[2] + "' is not a count");
                    }
                    if (count < 0 || count > Integer.MAX_VALUE / 9) throw new MeshProblem(where + "element count " + count + " is out of range");
                    elements.add(new Element(w[1], count, new ArrayList<>()));
                }
                case "property" -> {
                    if (elements.isEmpty()) throw new MeshProblem(where + "a property before any element");
                    List<Property> props = elements.get(elements.size() - 1).properties();
                    if (w.length >= 5 && w[1].equals("list")) props.add(new Property(w[4], w[3], w[2]));
                    else if (w.length >= 3) props.add(new Property(w[2], w[1], null));
                    else throw new MeshProblem(where + "a property needs a type and a name");
                    Property p = props.get(props.size() - 1);
                    size(p.type(), where);
                    if (p.countType() != null) size(p.countType(), where);
                }
                default -> { }
            }
        }
        if (format == null) throw new MeshProblem("the PLY header has no format line");
        boolean ascii = format.equals("ascii");
        if (!ascii && !format.equals("binary_little_endian")) {
            throw new MeshProblem("PLY format '" + format + "' is not read; use ascii or binary_little_endian");
        }
        Reader in = ascii ? new AsciiReader(bytes, pos) : new BinaryReader(bytes, pos);
        int[] corners = new int[48];
        for (Element e : elements) {
            boolean vertex = e.name().equals("vertex"), face = e.name().equals("face");
            int x = find(e, "x"), y = find(e, "y"), z = find(e, "z");
            int nx = find(e, "nx"), ny = find(e, "ny"), nz = find(e, "nz");
            int u = Math.max(find(e, "u"), Math.max(find(e, "s"), find(e, "texture_u")));
            int v = Math.max(find(e, "v"), Math.max(find(e, "t"), find(e, "texture_v")));
            if (vertex && (x < 0 || y < 0 || z < 0)) throw new MeshProblem("the PLY vertex element has no x, y and z");
            int list = -1;
            for (int k = 0; k < e.properties().size(); k++) {
                Property p = e.properties().get(k);
                if (p.countType() != null && (p.name().equals("vertex_indices") || p.name().equals("vertex_index"))) list = k;
            }
            if (face && list < 0) throw new MeshProblem("the PLY face element has no vertex_indices list");
            double[] values = new double[e.properties().size()];
            int[] types = new int[values.length], countTypes = new int[values.length];
            for (int k = 0; k < values.length; k++) {
                Property p = e.properties().get(k);
                types[k] = code(p.type());
                countTypes[k] = p.countType() == null ? -1 : code(p.countType());
            }
            Place where = new Place(e.name());
            if (in instanceof BinaryReader binary) {
                if (vertex && binaryVertices(binary, e, types, countTypes, x, y, z, nx, ny, nz, u, v, b, where)) continue;
                if (face && binaryFaces(binary, e, types, countTypes, b, where)) continue;
            }
            for (long i = 0; i < e.count(); i++) {
                where.index = i;
                try {
                    for (int k = 0; k < values.length; k++) {
                        if (countTypes[k] < 0) {
                            values[k] = in.next(types[k], where);
                            continue;
                        }
                        double count = in.next(countTypes[k], where);
                        if (!(count >= 0 && count <= 1 << 16) || count != Math.rint(count)) {
                            throw new MeshProblem(where + "a list length of " + count);
                        }
                        int n = (int) count;
                        if (k == list && face) {
                            if (3 * n > corners.length) corners = new int[3 * n];
                            for (int c = 0; c < n; c++) {
                                double index = in.next(types[k], where);
                                if (index != Math.rint(index) || Math.abs(index) > Integer.MAX_VALUE) {
                                    throw new MeshProblem(where + "vertex index " + index + " is not a whole number");
                                }
                                corners[3 * c] = (int) index;
                                corners[3 * c + 1] = -1;
                                corners[3 * c + 2] = -1;
                            }
                        } else {
                            for (int c = 0; c < n; c++) in.next(types[k], where);
                        }
                        if (k == list && face) values[k] = n;
                    }
                } catch (BufferUnderflowException | IndexOutOfBoundsException end) {
                    throw new MeshProblem("the file ends at " + e.name() + " " + i + " of " + e.count()
                            + " " + e.name() + " elements (truncated?)");
                }
                if (vertex) {
                    b.position(values[x], values[y], values[z], where);
                    if (nx >= 0 && ny >= 0 && nz >= 0) b.normal(values[nx], values[ny], values[nz], where);
                    if (u >= 0 && v >= 0) b.uv(values[u], values[v], where);
                } else if (face) {
                    int n = (int) values[list];
                    boolean normals = b.normals() == b.positions(), uvs = b.uvs() == b.positions();
                    for (int c = 0; c < n; c++) {
                        if (normals) corners[3 * c + 2] = corners[3 * c];
                        if (uvs) corners[3 * c + 1] = corners[3 * c];
                    }
                    b.polygon(corners, n, where);
                }
            }
        }
    }

    /**
     * Binary vertices whose properties are all scalars, read at fixed offsets of a fixed stride
     * (the common case, and most of a large file) rather than value by value; false, reading
     * nothing, for any other layout. The same values and problems as the general loop.
     */
    private static boolean binaryVertices(BinaryReader in, Element e, int[] types, int[] countTypes, int x, int y, int z,
            int nx, int ny, int nz, int u, int v, MeshBuilder b, Place where) throws MeshProblem {
        int[] at = new int[types.length];
        int stride = 0;
        for (int k = 0; k < types.length; k++) {
            if (countTypes[k] >= 0) return false;
            at[k] = stride;
            stride += width(types[k]);
        }
        boolean normals = nx >= 0 && ny >= 0 && nz >= 0, uvs = u >= 0 && v >= 0;
        ByteBuffer buffer = in.buffer;
        int pos = buffer.position(), limit = buffer.limit();
        for (long i = 0; i < e.count(); i++, pos += stride) {
            where.index = i;
            if (pos + stride > limit) {
                throw new MeshProblem("the file ends at " + e.name() + " " + i + " of " + e.count() + " " + e.name() + " elements (truncated?)");
            }
            b.position(value(buffer, pos + at[x], types[x]), value(buffer, pos + at[y], types[y]), value(buffer, pos + at[z], types[z]), where);
            if (normals) {
                b.normal(value(buffer, pos + at[nx], types[nx]), value(buffer, pos + at[ny], types[ny]),
                        value(buffer, pos + at[nz], types[nz]), where);
            }
            if (uvs) b.uv(value(buffer, pos + at[u], types[u]), value(buffer, pos + at[v], types[v]), where);
        }
        buffer.position(pos);
        return true;
    }

    /**
     * Binary faces made of the vertex index list alone, with an 8-bit length and 32-bit indices
     * (the common case), read without going value by value; false, reading nothing, for any
     * other layout. The same polygons and problems as the general loop.
     */
    private static boolean binaryFaces(BinaryReader in, Element e, int[] types, int[] countTypes, MeshBuilder b, Place where)
            throws MeshProblem {
        if (types.length != 1 || !(countTypes[0] == UINT8 || countTypes[0] == INT8) || !(types[0] == INT32 || types[0] == UINT32)) {
            return false;
        }
        boolean unsigned = types[0] == UINT32, signedCount = countTypes[0] == INT8;
        ByteBuffer buffer = in.buffer;
        int pos = buffer.position(), limit = buffer.limit();
        int[] corners = new int[3 * 256];
        for (long i = 0; i < e.count(); i++) {
            where.index = i;
            if (pos >= limit) throw truncated(e, i);
            int n = signedCount ? buffer.get(pos) : buffer.get(pos) & 0xff;
            if (n < 0) throw new MeshProblem(where + "a list length of " + (double) n);
            pos++;
            if (pos + 4L * n > limit) throw truncated(e, i);
            for (int c = 0; c < n; c++, pos += 4) {
                int index = buffer.getInt(pos);
                // As the general loop: a value beyond ±(2³¹ − 1) is no index.
                if (unsigned && index < 0 || index == Integer.MIN_VALUE) {
                    double value = unsigned ? index & 0xffffffffL : index;
                    throw new MeshProblem(where + "vertex index " + value + " is not a whole number");
                }
                corners[3 * c] = index;
            }
            // Faces of positions alone: every corner's uv and normal are those of its position
            // when the vertices gave them, none otherwise.
            boolean normals = b.normals() == b.positions(), uvs = b.uvs() == b.positions();
            for (int c = 0; c < n; c++) {
                corners[3 * c + 1] = uvs ? corners[3 * c] : -1;
                corners[3 * c + 2] = normals ? corners[3 * c] : -1;
            }
            b.polygon(corners, n, where);
        }
        buffer.position(pos);
        return true;
    }

    private static MeshProblem truncated(Element e, long i) {
        return new MeshProblem("the file ends at " + e.name() + " " + i + " of " + e.count() + " " + e.name() + " elements (truncated?)");
    }

    private static int width(int type) {
        return switch (type) {
            case INT8, UINT8 -> 1;
            case INT16, UINT16 -> 2;
            case INT32, UINT32, FLOAT32 -> 4;
            default -> 8;
        };
    }

    /** The value of {@code type} at {@code pos} of a little-endian buffer, as {@link BinaryReader#next} reads it. */
    private static double value(ByteBuffer buffer, int pos, int type) {
        return switch (type) {
            case INT8 -> buffer.get(pos);
            case UINT8 -> buffer.get(pos) & 0xff;
            case INT16 -> buffer.getShort(pos);
            case UINT16 -> buffer.getShort(pos) & 0xffff;
            case INT32 -> buffer.getInt(pos);
            case UINT32 -> buffer.getInt(pos) & 0xffffffffL;
            case FLOAT32 -> buffer.getFloat(pos);
            default -> buffer.getDouble(pos);
        };
    }

    private static int find(Element e, String name) {
        for (int k = 0; k < e.properties().size(); k++) {
            Property p = e.properties().get(k);
            if (p.countType() == null && p.name().equals(name)) return k;
        }
        return -1;
    }

    private static int size(String type, String where) throws MeshProblem {
        return switch (type) {
            case "char", "uchar", "int8", "uint8" -> 1;
            case "short", "ushort", "int16", "uint16" -> 2;
            case "int", "uint", "float", "int32", "uint32", "float32" -> 4;
            case "double", "float64" -> 8;
            default -> throw new MeshProblem(where + "unknown PLY type '" + type + "'");
        };
    }

    private static final int INT8 = 0, UINT8 = 1, INT16 = 2, UINT16 = 3, INT32 = 4, UINT32 = 5, FLOAT32 = 6, FLOAT64 = 7;

    /** A PLY type name as one of the codes above, decided once per property rather than per value. */
    private static int code(String type) {
        return switch (type) {
            case "char", "int8" -> INT8;
            case "uchar", "uint8" -> UINT8;
            case "short", "int16" -> INT16;
            case "ushort", "uint16" -> UINT16;
            case "int", "int32" -> INT32;
            case "uint", "uint32" -> UINT32;
            case "float", "float32" -> FLOAT32;
            default -> FLOAT64;
        };
    }

    /** "vertex 12: " or "line 7: ", made into text only when a problem is reported, not for every element read. */
    private static final class Place {
        final String what;
        long index;

        Place(String what) { this.what = what; }

        @Override
        public String toString() { return what + " " + index + ": "; }
    }

    private interface Reader {
        double next(int type, Object where) throws MeshProblem;
    }

    private static final class BinaryReader implements Reader {
        final ByteBuffer buffer;

        BinaryReader(byte[] bytes, int start) {
            buffer = ByteBuffer.wrap(bytes, start, bytes.length - start).order(ByteOrder.LITTLE_ENDIAN);
        }

        @Override
        public double next(int type, Object where) {
            return switch (type) {
                case INT8 -> buffer.get();
                case UINT8 -> buffer.get() & 0xff;
                case INT16 -> buffer.getShort();
                case UINT16 -> buffer.getShort() & 0xffff;
                case INT32 -> buffer.getInt();
                case UINT32 -> buffer.getInt() & 0xffffffffL;
                case FLOAT32 -> buffer.getFloat();
                default -> buffer.getDouble();
            };
        }
    }

    private static final class AsciiReader implements Reader {
        private final byte[] bytes;
        private int pos;

        AsciiReader(byte[] bytes, int start) {
            this.bytes = bytes;
            this.pos = start;
        }

        @Override
        public double next(int type, Object where) throws MeshProblem {
            while (pos < bytes.length && Character.isWhitespace(bytes[pos])) pos++;
            if (pos >= bytes.length) throw new BufferUnderflowException();
            int start = pos;
            while (pos < bytes.length && !Character.isWhitespace(bytes[pos])) pos++;
            return parse(new String(bytes, start, pos - start, StandardCharsets.ISO_8859_1), where);
        }
    }
}

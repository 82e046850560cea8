package org.kdtree.io;

import org.kdtree.limits.Limit;

import com.google.gson.stream.JsonReader;
import com.google.gson.stream.JsonToken;
import com.google.gson.stream.MalformedJsonException;
import java.io.EOFException;
import java.io.IOException;
import java.io.Reader;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A parsed JSON value that remembers where it came from (file, line, and its path such as
 * {@code $.lights[1].samples}), so that every error about a scene file names the file, the
 * line and the field. Read with gson's streaming {@link JsonReader} (strict: no comments).
 */
public final class JsonNode {
    private static final Pattern LINE = Pattern.compile("line (\\d+)");

    private final Object value;   // Map<String, JsonNode>, List<JsonNode>, String, Double (as text), Boolean, null
    private final boolean number;
    private final String file;
    private final int line;
    private final String path;

    private JsonNode(Object value, boolean number, String file, int line, String path) {
        this.value = value;
        this.number = number;
        this.file = file;
        this.line = line;
        this.path = path;
    }

    /** Parses one JSON document; syntax errors become {@link SceneFormatException}s with the line. */
    public static JsonNode parse(Reader reader, String file) throws SceneFormatException {
        String text;
        try {
            text = new java.io.BufferedReader(reader).lines().collect(java.util.stream.Collectors.joining("\n"));
        } catch (java.io.UncheckedIOException e) {
            throw new SceneFormatException(file, 0, e.getCause().getMessage());
        }
        JsonReader in = new JsonReader(new java.io.StringReader(text));
        try {
            JsonNode root = read(in, file, 0);
            if (in.peek() != JsonToken.END_DOCUMENT)
                throw new SceneFormatException(file, lineOf(in), "unexpected content after the end of the scene");
            return root;
        } catch (MalformedJsonException e) {
            throw new SceneFormatException(file, lineOf(in), JsonSyntax.explain(e.getMessage(), text));
        } catch (IllegalStateException | NumberFormatException e) {
            throw new SceneFormatException(file, lineOf(in), "malformed JSON: " + e.getMessage());
        } catch (EOFException e) {
            throw new SceneFormatException(file, lineOf(in), "unexpected end of file");
        } catch (SceneFormatException e) {
            throw e;
        } catch (IOException e) {
            throw new SceneFormatException(file, lineOf(in), e.getMessage());
        }
    }

    /** How deep arrays and objects may nest: a scene needs 4 levels; 100,000 would overflow the stack. */
    static final int MAX_NESTING = 64;

    private static JsonNode read(JsonReader in, String file, int depth) throws IOException {
        if (depth > MAX_NESTING)
            throw new SceneFormatException(file, lineOf(in), "arrays and objects nested deeper than "
                    + MAX_NESTING + " levels; a scene needs no more than 4");
        JsonToken token = in.peek();
        int line = lineOf(in);
        String path = in.getPath();
        switch (token) {
            case BEGIN_OBJECT -> {
                Map<String, JsonNode> fields = new LinkedHashMap<>();
                in.beginObject();
                while (in.hasNext()) {
                    String name = in.nextName();
                    if (fields.containsKey(name))
                        throw new SceneFormatException(file, lineOf(in), in.getPath() + ": field '" + name + "' given twice");
                    fields.put(name, read(in, file, depth + 1));
                }
                in.endObject();
                return new JsonNode(fields, false, file, line, path);
            }
            case BEGIN_ARRAY -> {
                List<JsonNode> items = new ArrayList<>();
                in.beginArray();
                while (in.hasNext()) items.add(read(in, file, depth + 1));
                in.endArray();
                return new JsonNode(items, false, file, line, path);
            }
            case STRING -> { return new JsonNode(in.nextString(), false, file, line, path); }
            case NUMBER -> { return new JsonNode(in.nextString(), true, file, line, path); }
            case BOOLEAN -> { return new JsonNode(in.nextBoolean(), false, file, line, path); }
            case NULL -> {
                in.nextNull();
                return new JsonNode(null, false, file, line, path);
            }
            default -> throw new SceneFormatException(file, line, "unexpected " + token);
        }
    }

    /** The reader's current line, from its location string (gson keeps the counter private). */
    private static int lineOf(JsonReader in) {
        Matcher m = LINE.matcher(in.toString());
        return m.find() ? Integer.parseInt(m.group(1)) : 0;
    }

    public String file() { return file; }
    public int line() { return line; }
    public String path() { return path; }

    /** An error about this value, naming file, line and field. */
    public SceneFormatException error(String problem) {
        return new SceneFormatException(file, line, path + ": " + problem);
    }

    public boolean isObject() { return value instanceof Map; }
    public boolean isArray() { return value instanceof List; }
    public boolean isString() { return value instanceof String && !number; }
    public boolean isNumber() { return number; }

    @SuppressWarnings("unchecked")
    private Map<String, JsonNode> fields() throws SceneFormatException {
        if (!isObject()) throw error("expected an object");
        return (Map<String, JsonNode>) value;
    }

    /** A required field of this object. */
    public JsonNode get(String name) throws SceneFormatException {
        JsonNode n = fields().get(name);
        if (n == null) throw error("missing field '" + name + "'");
        return n;
    }

    /** An optional field of this object, or null. */
    public JsonNode opt(String name) throws SceneFormatException {
        return fields().get(name);
    }

    public boolean has(String name) throws SceneFormatException { return fields().containsKey(name); }

    public Set<String> fieldNames() throws SceneFormatException { return fields().keySet(); }

    /** Rejects fields outside {@code known}: a typo should not be silently ignored. */
    public JsonNode allowOnly(String... known) throws SceneFormatException {
        Set<String> ok = Set.of(known);
        for (Map.Entry<String, JsonNode> e : fields().entrySet())
            if (!ok.contains(e.getKey()))
                throw e.getValue().error("unknown field '" + e.getKey() + "' (expected one of " + String.join(", ", known) + ")");
        return this;
    }

    @SuppressWarnings("unchecked")
    public List<JsonNode> array() throws SceneFormatException {
        if (!isArray()) throw error("expected an array");
        return (List<JsonNode>) value;
    }

    public String string() throws SceneFormatException {
        if (!isString()) throw error("expected a string");
        return (String) value;
    }

    public boolean bool() throws SceneFormatException {
        if (!(value instanceof Boolean b)) throw error("expected true or false");
        return b;
    }

    /** A finite number. */
    public double number() throws SceneFormatException {
        if (!number) throw error("expected a number");
        double d = Double.parseDouble((String) value);
        if (!Double.isFinite(d)) throw error("number out of range");
        return d;
    }

    /** A number at least {@code min}. */
    public double number(double min) throws SceneFormatException {
        double d = number();
        if (d < min) throw error("must be at least " + min + ", got " + d);
        return d;
    }

    /** An integer in [min, max]. */
    public int integer(int min, int max) throws SceneFormatException {
        return integer(Limit.whole("value", min, max));
    }

    /** A whole number that {@code limit} allows. */
    public int integer(Limit limit) throws SceneFormatException {
        double d = number();
        if (d != Math.rint(d)) throw error("expected a whole number, got " + value);
        if (!limit.allows(d)) throw error(limit.requirement() + ", got " + value);
        return (int) d;
    }

    /** Three numbers {@code [x, y, z]}, or a single number meaning all three. */
    public double[] triple() throws SceneFormatException {
        if (number) {
            double d = number();
            return new double[] {d, d, d};
        }
        List<JsonNode> a = array();
        if (a.size() != 3) throw error("expected [x, y, z], got " + a.size() + " numbers");
        return new double[] {a.get(0).number(), a.get(1).number(), a.get(2).number()};
    }

    @Override public String toString() { return path + " at " + file + ":" + line; }
}

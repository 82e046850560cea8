package org.kdtree.io;

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
import org.kdtree.limits.Limit;

/**
 * A parsed JSON value that remembers where it came from (file, line, and its path such as
 * {@code $.lights[1].samples}), so that every error about a scene file names the file, the
 * line and the field. Read with gson's streaming {@link JsonReader} (strict: no comments).
 */
final class JsonNode {
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

    /**
     * Parses one JSON document; syntax errors become {@link SceneFormatException}s with the line.
     *
     * @param reader the JSON text
     * @param file the file name errors give
     * @return the document's root value
     * @throws SceneFormatException for a syntax error or a file that is not one JSON value
     */
    public static JsonNode read(Reader reader, String file) throws SceneFormatException {
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

    /** {@return the name of the file this value came from} */
    public String file() { return file; }
    /** {@return the 1-based line this value starts on} */
    public int line() { return line; }
    /** {@return this value's path in the document, such as {@code $.lights[1].samples}} */
    public String path() { return path; }

    /**
     * {@return an error about this value, naming file, line and field}
     *
     * @param problem what is wrong
     */
    public SceneFormatException error(String problem) {
        return new SceneFormatException(file, line, path + ": " + problem);
    }

    /** {@return whether this value is a JSON object} */
    public boolean isObject() { return value instanceof Map; }
    /** {@return whether this value is a JSON array} */
    public boolean isArray() { return value instanceof List; }
    /** {@return whether this value is a JSON string} */
    public boolean isString() { return value instanceof String && !number; }
    /** {@return whether this value is a JSON number} */
    public boolean isNumber() { return number; }

    @SuppressWarnings("unchecked")
    private Map<String, JsonNode> fields() throws SceneFormatException {
        if (!isObject()) throw error("expected an object");
        return (Map<String, JsonNode>) value;
    }

    /**
     * {@return a required field of this object}
     *
     * @param name the field's name
     * @throws SceneFormatException if this is not an object or the field is missing
     */
    public JsonNode get(String name) throws SceneFormatException {
        JsonNode n = fields().get(name);
        if (n == null) throw error("missing field '" + name + "'");
        return n;
    }

    /**
     * {@return whether this object has the field}
     *
     * @param name the field's name
     * @throws SceneFormatException if this is not an object
     */
    public boolean has(String name) throws SceneFormatException { return fields().containsKey(name); }

    /**
     * {@return the names of this object's fields}
     *
     * @throws SceneFormatException if this is not an object
     */
    public Set<String> fieldNames() throws SceneFormatException { return fields().keySet(); }

    /**
     * Rejects fields outside {@code known}: a typo should not be silently ignored.
     *
     * @param known the field names allowed
     * @return this object
     * @throws SceneFormatException naming the first unknown field, or if this is not an object
     */
    public JsonNode allowOnly(String... known) throws SceneFormatException {
        Set<String> ok = Set.of(known);
        for (Map.Entry<String, JsonNode> e : fields().entrySet())
            if (!ok.contains(e.getKey()))
                throw e.getValue().error("unknown field '" + e.getKey() + "' (expected one of " + String.join(", ", known) + ")");
        return this;
    }

    /**
     * {@return this array's elements}
     *
     * @throws SceneFormatException if this is not an array
     */
    @SuppressWarnings("unchecked")
    public List<JsonNode> array() throws SceneFormatException {
        if (!isArray()) throw error("expected an array");
        return (List<JsonNode>) value;
    }

    /**
     * {@return this string}
     *
     * @throws SceneFormatException if this is not a string
     */
    public String string() throws SceneFormatException {
        if (!isString()) throw error("expected a string");
        return (String) value;
    }

    /**
     * {@return this boolean}
     *
     * @throws SceneFormatException if this is not true or false
     */
    public boolean bool() throws SceneFormatException {
        if (!(value instanceof Boolean b)) throw error("expected true or false");
        return b;
    }

    /**
     * {@return this number, which must be finite}
     *
     * @throws SceneFormatException if this is not a finite number
     */
    public double number() throws SceneFormatException {
        if (!number) throw error("expected a number");
        double d = Double.parseDouble((String) value);
        if (!Double.isFinite(d)) throw error("number out of range");
        return d;
    }

    /**
     * {@return this number, which must be at least {@code min}}
     *
     * @param min the smallest value allowed
     * @throws SceneFormatException if this is not a number or is below {@code min}
     */
    public double number(double min) throws SceneFormatException {
        double d = number();
        if (d < min) throw error("must be at least " + min + ", got " + d);
        return d;
    }

    /**
     * {@return this number, which must be an integer in [min, max]}
     *
     * @param min the smallest value allowed
     * @param max the largest value allowed
     * @throws SceneFormatException if this is not such an integer
     */
    public int integer(int min, int max) throws SceneFormatException {
        return integer(Limit.whole("value", min, max));
    }

    /**
     * {@return this number, which must be a whole number that {@code limit} allows}
     *
     * @param limit the allowed range
     * @throws SceneFormatException if this is not such a number
     */
    public int integer(Limit limit) throws SceneFormatException {
        double d = number();
        if (d != Math.rint(d)) throw error("expected a whole number, got " + value);
        if (!limit.allows(d)) throw error(limit.requirement() + ", got " + value);
        return (int) d;
    }

    /**
     * {@return three numbers {@code [x, y, z]}}, or a single number meaning all three.
     *
     * @throws SceneFormatException if this is neither a number nor an array of three numbers
     */
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

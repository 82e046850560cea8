package org.kdtree.io;

import de.javagl.obj.FloatTuple;
import de.javagl.obj.Mtl;
import de.javagl.obj.MtlReader;
import java.io.IOException;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.kdtree.scene.Material;
import org.kdtree.scene.Vec3;

/**
 * Reads MTL material libraries into renderer {@link Material}s and maps the MTL illumination
 * models ({@code illum 0-10}) onto the same effects the renderer plans for:
 *
 * <table>
 * <caption>illum model to material</caption>
 * <tr><th>illum</th><th>MTL meaning</th><th>material</th></tr>
 * <tr><td>0</td><td>colour on, ambient off</td><td>unlit constant colour Kd (no shadow rays)</td></tr>
 * <tr><td>1</td><td>colour and ambient on</td><td>diffuse Kd</td></tr>
 * <tr><td>2</td><td>highlight on</td><td>diffuse Kd + Phong Ks, Ns</td></tr>
 * <tr><td>3</td><td>reflection on, ray trace on</td><td>as 2 + mirror reflectivity Ks</td></tr>
 * <tr><td>4</td><td>glass on, ray trace on</td><td>as 3 + straight transmission Tf (no bending)</td></tr>
 * <tr><td>5</td><td>Fresnel reflection, ray trace on</td><td>as 3 (Fresnel for opaque surfaces is not modelled)</td></tr>
 * <tr><td>6</td><td>refraction on, Fresnel off, ray trace on</td><td>as 3 + refraction Tf with IOR Ni</td></tr>
 * <tr><td>7</td><td>refraction on, Fresnel on, ray trace on</td><td>as 6, reflection and refraction weighted by Fresnel</td></tr>
 * <tr><td>8</td><td>reflection on, ray trace off</td><td>as 2 (no reflection rays)</td></tr>
 * <tr><td>9</td><td>glass on, ray trace off</td><td>diffuse + Phong + straight transmission Tf, no reflection rays</td></tr>
 * <tr><td>10</td><td>shadows on invisible surfaces</td><td>as 1 (shadow catchers are not modelled)</td></tr>
 * </table>
 * A missing {@code illum} means 2 when Ks is non-zero, else 1. Transmission is Tf if given,
 * else {@code 1 - d} if d is given, else white.
 *
 * <p>The library itself is parsed by de.javagl:obj's {@link MtlReader}; a line-by-line check of
 * our own runs first, because that reader does not report where a malformed value is.
 */
final class MaterialReader {
    private static final Set<String> COLORS = Set.of("Ka", "Kd", "Ks", "Ke", "Tf");
    private static final Set<String> SCALARS = Set.of("Ns", "Ni", "d", "Tr", "sharpness");

    private MaterialReader() {
    }

    /**
     * {@return a material library read from {@code file}: material name to material}
     *
     * @param file the MTL file
     * @throws IOException if the file cannot be read or is malformed
     */
    public static Map<String, Material> read(Path file) throws IOException {
        if (!Files.isRegularFile(file)) throw new SceneFormatException(file.toString(), 0, "no such material library");
        String text = TextLines.readAll(file);
        check(text, file.toString());
        List<Mtl> mtls;
        try {
            mtls = MtlReader.read(new StringReader(text));
        } catch (IOException | RuntimeException e) {
            throw new SceneFormatException(file.toString(), 0, e.getMessage());
        }
        Map<String, Material> out = new LinkedHashMap<>();
        for (Mtl m : mtls) out.put(m.getName(), toMaterial(m));
        return out;
    }

    /** Checks every line we use, so that errors name the line. */
    static void check(String text, String name) throws SceneFormatException {
        String[] lines = text.split("\r?\n", -1);
        boolean open = false;
        for (int i = 0; i < lines.length; i++) {
            String s = lines[i].strip();
            if (s.isEmpty() || s.startsWith("#")) continue;
            String[] t = s.split("\\s+");
            String key = t[0];
            if (key.equals("newmtl")) {
                if (t.length < 2) throw new SceneFormatException(name, i + 1, "newmtl needs a name");
                open = true;
            } else if (COLORS.contains(key) || SCALARS.contains(key) || key.equals("illum")) {
                if (!open) throw new SceneFormatException(name, i + 1, key + " before any newmtl");
                if (COLORS.contains(key) && (t.length == 2 || t.length == 4)) {
                    for (int k = 1; k < t.length; k++) number(t[k], key, name, i + 1);
                } else if (SCALARS.contains(key) && t.length == 2) {
                    number(t[1], key, name, i + 1);
                } else if (key.equals("illum") && t.length == 2) {
                    // written as digits only: the MTL reader takes it as an int, and "2.0" is not one
                    if (!t[1].matches("\\d{1,2}") || Integer.parseInt(t[1]) > 10)
                        throw new SceneFormatException(name, i + 1, "illum must be a whole number from 0 to 10 (digits only), got " + t[1]);
                } else {
                    throw new SceneFormatException(name, i + 1, key + ": wrong number of values in '" + s + "'");
                }
            }
        }
    }

    private static double number(String token, String key, String name, int line) throws SceneFormatException {
        try {
            double d = Double.parseDouble(token);
            if (Double.isFinite(d) && d >= 0) return d;
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new SceneFormatException(name, line, key + ": '" + token + "' is not a non-negative number");
    }

    /**
     * {@return the MTL illumination model mapped onto a renderer material} (see the class comment).
     *
     * @param m the MTL material
     */
    private static Material toMaterial(Mtl m) {
        Vec3 kd = color(m.getKd(), Vec3.ZERO), ks = color(m.getKs(), Vec3.ZERO), ke = color(m.getKe(), Vec3.ZERO);
        double ns = m.getNs() != null ? m.getNs() : 1;
        double ni = m.getNi() != null && m.getNi() > 0 ? m.getNi() : 1;
        int illum = m.getIllum() != null ? m.getIllum() : ks.isZero() ? 1 : 2;
        Vec3 tf = m.getTf() != null ? color(m.getTf(), Vec3.ONE)
                : m.getD() != null ? Vec3.ONE.times(1 - m.getD()) : Vec3.ONE;
        Vec3 specular = illum >= 2 && illum != 10 ? ks : Vec3.ZERO;
        Vec3 reflect = switch (illum) {
            case 3, 4, 5, 6, 7 -> ks;
            default -> Vec3.ZERO;
        };
        Vec3 transmit = switch (illum) {
            case 4, 6, 7, 9 -> tf;
            default -> Vec3.ZERO;
        };
        double ior = illum == 6 || illum == 7 ? ni : 1;
        if (illum == 7 && reflect.isZero()) reflect = Vec3.ONE;   // Fresnel decides how much
        if (illum == 0) return new Material(m.getName(), Vec3.ZERO, Vec3.ZERO, 1, Vec3.ZERO, Vec3.ZERO, 1, false, false, kd);
        return new Material(m.getName(), kd, specular, ns, reflect, transmit, ior, illum == 7, true, ke);
    }

    private static Vec3 color(FloatTuple t, Vec3 absent) {
        if (t == null) return absent;
        return t.getDimensions() >= 3 ? new Vec3(t.getX(), t.getY(), t.getZ()) : Vec3.ONE.times(t.getX());
    }
}

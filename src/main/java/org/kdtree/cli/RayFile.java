package org.kdtree.cli;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.PrintWriter;
import java.util.Locale;
import org.kdtree.accel.Hit;
import org.kdtree.accel.RayQuery;
import org.kdtree.geom.Ray;
import org.kdtree.io.SceneFormatException;

/**
 * The ray-file mode of {@code raycast} (bench SPEC, last section): one ray per line,
 * {@code ox oy oz dx dy dz [tmin tmax]} (defaults 0 and +infinity), whitespace separated,
 * {@code #} starting a comment line, blank lines ignored. The direction is used as given, so t is
 * the ray parameter. One output line per ray, in order: {@code t triangle} (t with 17
 * significant digits, enough to read the same double back) or {@code miss}.
 *
 * <p>A direction far from unit length (largest component below 2^-64 or above 2^64, down to the
 * smallest subnormal) is traced rescaled by a power of two, which is exact, with tmin and tmax
 * rescaled alike and t scaled back, so the answer is the same ray parameter; a hit whose t is
 * beyond the largest double (a direction so short that the ray parameter overflows) is refused
 * with the file and line.
 */
final class RayFile {
    /** Directions whose largest component has a binary exponent within this of 0 are traced as given. */
    private static final int ORDINARY_EXPONENT = 64;

    private RayFile() {
    }

    /**
     * Traces every ray of {@code in} with {@code query}, writing one line per ray; returns the ray count.
     *
     * @param in    the ray file, read to its end
     * @param name  the file's name, for error messages
     * @param query the query that finds each ray's closest hit
     * @param out   where the result lines go (flushed at the end)
     * @return the number of rays traced
     * @throws IOException if {@code in} cannot be read, or a line is malformed
     *                     ({@link SceneFormatException}, with the line number)
     */
    public static long trace(BufferedReader in, String name, RayQuery query, PrintWriter out) throws IOException {
        Ray ray = new Ray(3);
        Hit hit = new Hit();
        double[] v = new double[8];
        String line;
        int lineNo = 0;
        long rays = 0;
        while ((line = in.readLine()) != null) {
            lineNo++;
            String s = line.strip();
            if (s.isEmpty() || s.startsWith("#")) continue;
            String[] tok = s.split("\\s+");
            if (tok.length != 6 && tok.length != 8)
                throw new SceneFormatException(name, lineNo, "expected 'ox oy oz dx dy dz' optionally followed by "
                        + "'tmin tmax', got " + tok.length + " values");
            v[6] = 0;
            v[7] = Double.POSITIVE_INFINITY;
            for (int k = 0; k < tok.length; k++) v[k] = number(tok[k], name, lineNo, k < 6);
            if (v[3] == 0 && v[4] == 0 && v[5] == 0) throw new SceneFormatException(name, lineNo, "direction is zero");
            int k = rescaling(v[3], v[4], v[5]);
            ray.set(v[0], v[1], v[2], Math.scalb(v[3], k), Math.scalb(v[4], k), Math.scalb(v[5], k));
            if (query.closestHit(ray, Math.scalb(v[6], -k), Math.scalb(v[7], -k), hit))
                out.println(String.format(Locale.ROOT, "%.17g %d", rayParameter(hit.t, k, name, lineNo), hit.primitive));
            else
                out.println("miss");
            rays++;
        }
        out.flush();
        if (out.checkError()) throw new IOException(name + ": the hits could not be written");
        return rays;
    }

    /**
     * The power of two that brings a direction far from unit length to a largest component in
     * [1, 2) (scaling by it is exact, subnormals included), or 0 for an ordinary direction.
     */
    static int rescaling(double dx, double dy, double dz) {
        double largest = Math.max(Math.abs(dx), Math.max(Math.abs(dy), Math.abs(dz)));
        int exponent = largest >= Double.MIN_NORMAL ? Math.getExponent(largest)
                : Math.getExponent(Math.scalb(largest, ORDINARY_EXPONENT)) - ORDINARY_EXPONENT;
        return Math.abs(exponent) > ORDINARY_EXPONENT ? -exponent : 0;
    }

    /** The hit's t for the direction as given: the traced t scaled back, refused if no double holds it. */
    private static double rayParameter(double tracedT, int k, String name, int line) throws SceneFormatException {
        double t = Math.scalb(tracedT, k);
        if (Double.isInfinite(t))
            throw new SceneFormatException(name, line, String.format(Locale.ROOT, "the direction (dx dy dz) is so short that "
                    + "the hit's t, about 1e%.0f, is beyond the largest double (1.8e308); give a longer direction",
                    Math.log10(tracedT) + k * Math.log10(2)));
        return t;
    }

    private static double number(String token, String name, int line, boolean finite) throws SceneFormatException {
        double d;
        try {
            d = Double.parseDouble(token);
        } catch (NumberFormatException e) {
            throw new SceneFormatException(name, line, "'" + token + "' is not a number");
        }
        if (Double.isNaN(d) || (finite && Double.isInfinite(d)))
            throw new SceneFormatException(name, line, "'" + token + "' is not a finite number");
        return d;
    }
}

package org.kdtree.cli;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.PrintWriter;
import java.util.Locale;
import org.kdtree.geom.Ray;
import org.kdtree.io.SceneFormatException;
import org.kdtree.traverse.Hit;
import org.kdtree.traverse.RayQuery;

/**
 * The ray-file mode of {@code raycast} (bench SPEC, last section): one ray per line,
 * {@code ox oy oz dx dy dz [tmin tmax]} (defaults 0 and +infinity), whitespace separated,
 * {@code #} starting a comment line, blank lines ignored. The direction is used as given, so t is
 * the ray parameter. One output line per ray, in order: {@code t triangle} (t with 17
 * significant digits, enough to read the same double back) or {@code miss}.
 */
final class RayFile {
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
            ray.set(v[0], v[1], v[2], v[3], v[4], v[5]);
            if (query.closestHit(ray, v[6], v[7], hit))
                out.println(String.format(Locale.ROOT, "%.17g %d", hit.t, hit.primitive));
            else
                out.println("miss");
            rays++;
        }
        out.flush();
        if (out.checkError()) throw new IOException(name + ": the hits could not be written");
        return rays;
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

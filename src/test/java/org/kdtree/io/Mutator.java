package org.kdtree.io;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.Random;

/** Mutations of a valid file, as a coverage-free fuzzer makes them: flipped and inserted bytes, cut and repeated stretches, odd tokens. */
final class Mutator {
    private static final String[] TOKENS = {" ", "\n", "-", ".", "e", "1e309", "-1e400", "NaN", "Infinity", "0", "-0",
            "99999999999", "/", "//", "#", "\"", "{", "}", "[", "]", ",", ":", "\uFEFF", "\u00e9", "v", "f", "newmtl", "illum",
            "2.0", "1e-320", "1e200", "\t", "\r\n", "\u0000"};

    private Mutator() {
    }

    static byte[] mutate(byte[] text, Random r) {
        byte[] b = text;
        int rounds = 1 + r.nextInt(6);
        for (int i = 0; i < rounds; i++) b = once(b, r);
        return b;
    }

    private static byte[] once(byte[] b, Random r) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        int at = b.length == 0 ? 0 : r.nextInt(b.length + 1);
        switch (r.nextInt(6)) {
            case 0 -> {   // flip a byte
                byte[] c = b.clone();
                if (c.length > 0) c[Math.min(at, c.length - 1)] ^= (byte) (1 << r.nextInt(8));
                return c;
            }
            case 1 -> {   // insert a token
                out.write(b, 0, at);
                out.writeBytes(TOKENS[r.nextInt(TOKENS.length)].getBytes(StandardCharsets.UTF_8));
                out.write(b, at, b.length - at);
            }
            case 2 -> {   // cut a stretch
                int len = Math.min(b.length - at, r.nextInt(12));
                out.write(b, 0, at);
                out.write(b, at + len, b.length - at - len);
            }
            case 3 -> {   // repeat a stretch, many times now and then
                int len = Math.min(b.length - at, 1 + r.nextInt(24));
                int times = r.nextInt(10) == 0 ? 2000 : 1 + r.nextInt(4);
                out.write(b, 0, at + len);
                for (int t = 0; t < times; t++) out.write(b, at, len);
                out.write(b, at + len, b.length - at - len);
            }
            case 4 -> {   // a random byte
                out.write(b, 0, at);
                out.write(r.nextInt(256));
                out.write(b, at, b.length - at);
            }
            default -> {  // swap two halves
                out.write(b, at, b.length - at);
                out.write(b, 0, at);
            }
        }
        return out.toByteArray();
    }
}

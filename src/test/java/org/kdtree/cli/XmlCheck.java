package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import javax.xml.parsers.DocumentBuilderFactory;

/** Checks an XML file as CI's readers of JUnit XML would: with xmllint where it is installed, and always with the JDK's parser. */
final class XmlCheck {
    private static boolean said;

    private XmlCheck() {
    }

    static void assertWellFormed(Path file) throws Exception {
        DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(file.toFile());   // throws on XML that is not well formed
        String path = System.getenv("PATH") == null ? "/usr/bin" : System.getenv("PATH");
        boolean installed = false;
        for (String dir : path.split(File.pathSeparator)) installed |= !dir.isEmpty() && new File(dir, "xmllint").canExecute();
        if (!installed) {
            if (!said) System.err.println("xmllint is not installed (apt-get install libxml2-utils): the JUnit XML checked by the JDK's parser only");
            said = true;
            return;
        }
        Process p = new ProcessBuilder("xmllint", "--noout", file.toString()).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(30, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).as("xmllint: " + out).isZero();
    }
}

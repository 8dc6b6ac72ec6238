package robosim.it;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/**
 * docs/DESIGN.md's module table names the modules the root pom builds: a module added, renamed or
 * removed without the design page saying so fails here.
 */
class DesignModulesTest {
    private static final String SECTION = "## Modules, packages and what they may depend on";
    private static final Pattern QUOTED = Pattern.compile("`([^`]+)`");

    @Test
    void theDesignPageNamesEveryModuleOfTheRootPomAndNoOther() throws Exception {
        Path root = LocalEnvironment.root();
        assertNotNull(root, "the checkout's root (the folder with testLoadFiles/) was not found");
        Set<String> built = pomModules(root.resolve("pom.xml"));
        Set<String> named = designModules(root.resolve("docs/DESIGN.md"));
        assertFalse(built.isEmpty(), "the root pom lists no <module>");

        Set<String> unnamed = new TreeSet<>(built);
        unnamed.removeAll(named);
        Set<String> noModule = new TreeSet<>(named);
        noModule.removeAll(built);
        assertEquals(Set.of(), unnamed, "modules of the root pom that docs/DESIGN.md's module table does not name");
        assertEquals(Set.of(), noModule, "names in docs/DESIGN.md's module table that are no module of the root pom");
    }

    /** @return the {@code <module>} entries of the pom's {@code <modules>} */
    private static Set<String> pomModules(Path pom) throws Exception {
        DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
        factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
        Element project = factory.newDocumentBuilder().parse(pom.toFile()).getDocumentElement();
        Set<String> modules = new TreeSet<>();
        NodeList lists = project.getElementsByTagName("modules");
        for (int i = 0; i < lists.getLength(); i++) {
            NodeList entries = ((Element) lists.item(i)).getElementsByTagName("module");
            for (int j = 0; j < entries.getLength(); j++) {
                modules.add(entries.item(j).getTextContent().trim());
            }
        }
        return modules;
    }

    /** @return the folders quoted in the first column of the module table, without a trailing slash */
    private static Set<String> designModules(Path design) throws IOException {
        Set<String> modules = new TreeSet<>();
        for (String row : tableRows(Files.readAllLines(design))) {
            String[] cells = row.split("\\|", -1);
            Matcher m = QUOTED.matcher(cells[1]);
            while (m.find()) {
                String name = m.group(1);
                modules.add(name.endsWith("/") ? name.substring(0, name.length() - 1) : name);
            }
        }
        return modules;
    }

    /** @return the rows of the first table after the module section's heading, header and rule left out */
    private static List<String> tableRows(List<String> lines) {
        int start = lines.indexOf(SECTION);
        if (start < 0) {
            throw new AssertionError("docs/DESIGN.md has no section '" + SECTION + "'");
        }
        List<String> rows = new ArrayList<>();
        boolean inTable = false;
        for (String line : lines.subList(start + 1, lines.size())) {
            if (line.startsWith("|")) {
                inTable = true;
                rows.add(line);
            } else if (inTable || line.startsWith("## ")) {
                break;
            }
        }
        if (rows.size() < 3) {
            throw new AssertionError("docs/DESIGN.md's section '" + SECTION + "' has no module table");
        }
        return rows.subList(2, rows.size());
    }
}

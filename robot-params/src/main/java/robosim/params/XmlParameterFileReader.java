package robosim.params;

import robosim.protocol.RobotParameters;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.dataformat.xml.XmlFactory;
import com.fasterxml.jackson.dataformat.xml.deser.FromXmlParser;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import javax.xml.stream.Location;
import javax.xml.stream.XMLInputFactory;
import javax.xml.stream.XMLStreamConstants;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamReader;
import robosim.protocol.LogLimiter;

/**
 * Reads the XML forms of a robot parameter file, in either of two layouts told apart by the root
 * element: RoboSim's {@code <robotParameters>}, whose children are one element per parameter
 * ({@code <robotWidth>425</robotWidth>}), repeated {@code <sonarUnit number x y th/>} elements and
 * an optional {@code <laser x y th maxRange/>}; and the original RoboSim manual's
 * {@code <robot><params>...</params></robot>}, with the same parameter elements and a
 * {@code <sonar>} of {@code <sonarUnit>} elements whose values are child elements
 * ({@code <sonarNumber>}, {@code <sonarX>}, {@code <sonarY>}, {@code <sonarTh>}). A file in the
 * original layout without a {@code <sonar>} takes its subclass model's sonars ({@link SonarDefaults}).
 *
 * <p>Defaults and rules are those of {@link ParameterFileReader}, so the two forms of one robot
 * give equal records. XML is stricter in three ways: element and attribute names are matched
 * exactly, an element or attribute the form does not know is an error, and a parameter may be
 * given only once. Every error names the file, the line of the offending element and the rule.
 *
 * <p>The file is read token by token with Jackson's {@link FromXmlParser}, not bound to a tree or
 * a bean: the tokens carry the line of each element, and repeated {@code <sonarUnit>} elements
 * simply arrive one after another.
 */
public final class XmlParameterFileReader {
    private static final String ROOT = "robotParameters";
    /** The original RoboSim manual's layout: {@code <robot><params>...</params></robot>}. */
    private static final String ORIGINAL_ROOT = "robot";
    private static final String PARAMS = "params";
    private static final List<String> ORIGINAL_SONAR = List.of("sonarNumber", "sonarX", "sonarY", "sonarTh");
    private static final Set<String> NUMBERS = Set.of("robotRadius", "robotDiagonal", "robotWidth",
            "robotLength", "robotLengthFront", "robotLengthRear", "maxVelocity", "maxRVelocity", "transAccel",
            "transDecel", "rotAccel", "rotDecel", "diffConvFactor", "sonarMaxRange");
    private static final Set<String> OTHERS = Set.of("class", "subclass", "robotShape", "hasGripper", "sonarNum", "sonarUnit", "laser");
    private static final List<String> SONAR_ATTRIBUTES = List.of("number", "x", "y", "th");
    /** The laser's attributes; with {@code laser} in front they are the {@code .p} keys. */
    private static final List<String> LASER_ATTRIBUTES = List.of("x", "y", "th", "maxRange");
    private static final XmlFactory FACTORY = factory();

    private final Path file;
    private final FromXmlParser parser;
    private final ParameterRules rules;
    private final Map<String, Integer> seen = new HashMap<>();

    private XmlParameterFileReader(Path file, FromXmlParser parser) {
        this.file = file;
        this.parser = parser;
        this.rules = new ParameterRules(file, ParameterRules.XML_FORM);
    }

    /** A parameter file names no DTD or entities; refusing them keeps a file from reaching outside itself. */
    private static XmlFactory factory() {
        XMLInputFactory input = XMLInputFactory.newFactory();
        input.setProperty(XMLInputFactory.SUPPORT_DTD, Boolean.FALSE);
        input.setProperty(XMLInputFactory.IS_SUPPORTING_EXTERNAL_ENTITIES, Boolean.FALSE);
        return XmlFactory.builder().xmlInputFactory(input).build();
    }

    /**
     * Reads a parameter file in the XML form.
     *
     * @param file the {@code .xml} file
     * @return the robot's parameters
     * @throws ParameterFileException naming the file, the line and the rule when the file is broken
     *                                or is not well-formed XML
     * @throws UncheckedIOException   when the file cannot be read
     */
    public static RobotParameters read(Path file) {
        try (InputStream in = Files.newInputStream(file);
             FromXmlParser parser = (FromXmlParser) FACTORY.createParser(in)) {
            return new XmlParameterFileReader(file, parser).root();
        } catch (JsonProcessingException e) {
            throw malformed(file, e);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read robot parameter file " + file, e);
        }
    }

    private RobotParameters root() throws IOException {
        XMLStreamReader stax = parser.getStaxReader();
        boolean original = stax.isStartElement() && ORIGINAL_ROOT.equals(stax.getLocalName());
        if (!stax.isStartElement() || !ROOT.equals(stax.getLocalName()) && !original) {
            String found = stax.isStartElement() ? "<" + LogLimiter.excerpt(stax.getLocalName()) + ">" : "missing";
            throw rules.error(stax.getLocation().getLineNumber(),
                    "the root element is " + found + ", expected <" + ROOT + "> or <" + ORIGINAL_ROOT + ">");
        }
        String root = original ? ORIGINAL_ROOT : ROOT;
        int rootLine = stax.getLocation().getLineNumber();
        JsonToken token = parser.nextToken();
        if (token == JsonToken.START_OBJECT) {
            while (parser.nextToken() == JsonToken.FIELD_NAME) {
                String name = parser.currentName();
                int line = line();
                parser.nextToken();
                if (original) {
                    params(name, line);
                } else {
                    element(ROOT, name, line);
                }
            }
        } else if (token == JsonToken.VALUE_STRING && !parser.getText().isBlank()) {
            throw rules.error(line(), "text " + ParameterRules.quote(parser.getText().trim()) + " in <" + root + ">: "
                    + "parameters are child elements");
        }
        // Jackson stops at the root's end; reading on lets the XML parser see anything after it
        if (parser.nextToken() != null) {
            throw rules.error(line(), "content after </" + root + ">");
        }
        if (original) {
            if (!seen.containsKey(PARAMS)) {
                throw rules.error(rootLine, "<" + ORIGINAL_ROOT + "> has no <" + PARAMS + ">");
            }
            if (!seen.containsKey("sonar")) {
                Integer at = seen.getOrDefault("subclass", seen.get(PARAMS));
                rules.modelSonars(SonarDefaults.of(file, at, rules.robotClassName(), rules.subclassName()), at);
            }
        }
        return rules.build();
    }

    /** Handles the one child of the original layout's {@code <robot>}: {@code <params>}. */
    private void params(String name, int line) throws IOException {
        if (!PARAMS.equals(name)) {
            throw isAttribute(name) ? rules.error(line, "unknown attribute " + LogLimiter.excerpt(name)
                    + " on <" + ORIGINAL_ROOT + ">")
                    : rules.error(line, "unknown element <" + LogLimiter.excerpt(name) + "> in <"
                            + ORIGINAL_ROOT + "> (it holds <"
                    + PARAMS + ">)");
        }
        Integer first = seen.putIfAbsent(PARAMS, line);
        if (first != null) {
            throw rules.error(line, "<" + PARAMS + "> is given twice (first at line " + first + ")");
        }
        forEachChild(PARAMS, line, (child, childLine) -> element(PARAMS, child, childLine));
    }

    /** A child element's handler; the parser stands on the child's value. */
    private interface Child {
        void handle(String name, int line) throws IOException;
    }

    /** Calls {@code child} for each child of an element that holds only elements; the parser stands on its value. */
    private void forEachChild(String name, int line, Child child) throws IOException {
        if (!parser.hasToken(JsonToken.START_OBJECT)) {
            if (parser.hasToken(JsonToken.VALUE_STRING) && !parser.getText().isBlank()) {
                throw rules.error(line, "<" + LogLimiter.excerpt(name) + "> holds elements, not text "
                        + ParameterRules.quote(parser.getText().trim()));
            }
            return;
        }
        while (parser.nextToken() == JsonToken.FIELD_NAME) {
            String inner = parser.currentName();
            int innerLine = line();
            parser.nextToken();
            if (isAttribute(inner)) {
                throw rules.error(line, "unknown attribute " + LogLimiter.excerpt(inner) + " on <"
                        + LogLimiter.excerpt(name) + ">");
            }
            if (inner.isEmpty()) {
                if (parser.getText().isBlank()) {
                    continue;
                }
                throw rules.error(innerLine, "<" + LogLimiter.excerpt(name) + "> holds elements, not text "
                        + ParameterRules.quote(parser.getText().trim()));
            }
            child.handle(inner, innerLine);
        }
    }

    /** Reads the original layout's {@code <sonarUnit>}: child elements sonarNumber, sonarX, sonarY, sonarTh. */
    private void originalSonarUnit(String name, int line) throws IOException {
        if (!"sonarUnit".equals(name)) {
            throw rules.error(line, "unknown element <" + LogLimiter.excerpt(name)
                    + "> in <sonar> (it holds <sonarUnit>)");
        }
        Map<String, String> values = new HashMap<>();
        forEachChild(name, line, (child, childLine) -> {
            if (!ORIGINAL_SONAR.contains(child)) {
                throw rules.error(childLine, "unknown element <" + LogLimiter.excerpt(child)
                        + "> in <sonarUnit> (known: "
                        + String.join(", ", ORIGINAL_SONAR) + ")");
            }
            if (values.put(child, text(child, childLine)) != null) {
                throw rules.error(childLine, "<" + LogLimiter.excerpt(child) + "> is given twice in one <sonarUnit>");
            }
        });
        for (String wanted : ORIGINAL_SONAR) {
            if (!values.containsKey(wanted)) {
                throw rules.error(line, "sonarUnit has no <" + wanted + "> (it needs " + String.join(", ", ORIGINAL_SONAR) + ")");
            }
        }
        rules.sonarUnit(values.get("sonarNumber"), values.get("sonarX"), values.get("sonarY"), values.get("sonarTh"), line);
    }

    /** Handles one parameter element of {@code container}; the parser stands on its value. */
    private void element(String container, String name, int line) throws IOException {
        if (isAttribute(name)) {
            throw rules.error(line, "unknown attribute " + LogLimiter.excerpt(name) + " on <" + container + ">");
        }
        if (name.isEmpty()) {
            throw rules.error(line, "text " + ParameterRules.quote(parser.getText().trim()) + " in <"
                    + container + ">: "
                    + "parameters are child elements");
        }
        boolean original = PARAMS.equals(container);
        if (!NUMBERS.contains(name) && !OTHERS.contains(name) && !(original && name.equals("sonar"))
                || original && name.equals("sonarUnit")) {
            throw rules.error(line, "unknown element <" + LogLimiter.excerpt(name) + "> in <" + container + ">");
        }
        Integer first = seen.putIfAbsent(name, line);
        if (first != null && !name.equals("sonarUnit")) {
            throw rules.error(line, "<" + LogLimiter.excerpt(name) + "> is given twice (first at line "
                    + first + ")");
        }
        switch (name) {
            case "class" -> rules.robotClass(text(name, line));
            case "subclass" -> rules.subclass(text(name, line));
            case "robotShape" -> rules.shape(text(name, line), line);
            case "hasGripper" -> rules.hasGripper(text(name, line), line);
            case "sonarNum" -> rules.sonarNum(text(name, line), line);
            case "sonar" -> forEachChild(name, line, this::originalSonarUnit);
            case "sonarUnit" -> {
                Map<String, String> a = attributes(name, line, SONAR_ATTRIBUTES);
                for (String wanted : SONAR_ATTRIBUTES) {
                    if (!a.containsKey(wanted)) {
                        throw rules.error(line, "sonarUnit has no attribute " + wanted
                                + " (it needs number, x, y and th)");
                    }
                }
                rules.sonarUnit(a.get("number"), a.get("x"), a.get("y"), a.get("th"), line);
            }
            case "laser" -> {
                Map<String, String> a = attributes(name, line, LASER_ATTRIBUTES);
                a.forEach((attribute, value) -> rules.number("laser" + attribute, "laser " + attribute, value, line));
            }
            default -> rules.number(name, text(name, line), line);
        }
    }

    /** @return the text of an element that holds only text, trimmed */
    private String text(String name, int line) throws IOException {
        if (parser.hasToken(JsonToken.START_OBJECT)) {
            parser.nextToken();
            String inner = parser.currentName();
            int innerLine = line();
            parser.nextToken();
            throw isAttribute(inner)
                    ? rules.error(line, "unknown attribute " + LogLimiter.excerpt(inner) + " on <"
                            + LogLimiter.excerpt(name) + ">")
                    : rules.error(innerLine, "unknown element <" + LogLimiter.excerpt(inner) + "> in <"
                            + LogLimiter.excerpt(name) + ">");
        }
        String text = parser.hasToken(JsonToken.VALUE_STRING) ? parser.getText().trim() : "";
        if (text.isEmpty()) {
            throw rules.error(line, name + " has no value");
        }
        return text;
    }

    /** @return the attributes of an element that holds only attributes, in file order */
    private Map<String, String> attributes(String name, int line, List<String> allowed) throws IOException {
        Map<String, String> found = new LinkedHashMap<>();
        if (!parser.hasToken(JsonToken.START_OBJECT)) {
            if (parser.hasToken(JsonToken.VALUE_STRING) && !parser.getText().isBlank()) {
                throw rules.error(line, "<" + LogLimiter.excerpt(name) + "> takes attributes, not text "
                        + ParameterRules.quote(parser.getText().trim()));
            }
            return found;
        }
        while (parser.nextToken() == JsonToken.FIELD_NAME) {
            String attribute = parser.currentName();
            int attributeLine = line();
            parser.nextToken();
            if (!isAttribute(attribute)) {
                if (attribute.isEmpty() && parser.getText().isBlank()) {
                    continue;
                }
                throw attribute.isEmpty()
                        ? rules.error(attributeLine, "<" + LogLimiter.excerpt(name) + "> takes attributes, not text '"
                                + parser.getText().trim() + "'")
                        : rules.error(attributeLine, "unknown element <" + LogLimiter.excerpt(attribute)
                                + "> in <" + LogLimiter.excerpt(name) + ">");
            }
            if (!allowed.contains(attribute)) {
                throw rules.error(line, "unknown attribute " + LogLimiter.excerpt(attribute) + " on <"
                        + LogLimiter.excerpt(name) + "> (known: "
                        + String.join(", ", allowed) + ")");
            }
            found.put(attribute, parser.getText().trim());
        }
        return found;
    }

    /**
     * Jackson reports attributes and child elements alike as fields; the StAX reader underneath
     * tells them apart: while an attribute's value is the current token, the reader still stands
     * on the start tag that carries it.
     */
    private boolean isAttribute(String name) {
        XMLStreamReader stax = parser.getStaxReader();
        return parser.hasToken(JsonToken.VALUE_STRING) && !name.isEmpty()
                && stax.getEventType() == XMLStreamConstants.START_ELEMENT
                && stax.getAttributeValue(null, name) != null;
    }

    private int line() {
        return parser.currentTokenLocation().getLineNr();
    }

    private static ParameterFileException malformed(Path file, JsonProcessingException e) {
        for (Throwable t = e; t != null; t = t.getCause()) {
            if (t instanceof XMLStreamException xml) {
                Location at = xml.getLocation();
                return new ParameterFileException(file, at == null ? 0 : at.getLineNumber(),
                        "malformed XML: " + firstLine(xml.getMessage()), e);
            }
        }
        int line = e.getLocation() == null ? 0 : e.getLocation().getLineNr();
        return new ParameterFileException(file, line, "malformed XML: " + firstLine(e.getOriginalMessage()), e);
    }

    /** @return the parser's first line, escaped and cut after 200 characters: it may quote the file */
    private static String firstLine(String message) {
        String text = String.valueOf(message);
        int end = text.indexOf('\n');
        return robosim.protocol.RobotHello.printable((end < 0 ? text : text.substring(0, end)).trim(), 200);
    }
}

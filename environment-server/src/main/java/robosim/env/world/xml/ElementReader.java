package robosim.env.world.xml;

import com.fasterxml.jackson.annotation.JsonAutoDetect;
import com.fasterxml.jackson.annotation.PropertyAccessor;
import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.module.SimpleModule;
import com.fasterxml.jackson.dataformat.xml.XmlMapper;
import com.fasterxml.jackson.dataformat.xml.deser.FromXmlParser;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import javax.xml.stream.Location;
import javax.xml.stream.XMLStreamException;
import javax.xml.stream.XMLStreamReader;
import robosim.protocol.LogLimiter;
import robosim.protocol.RobotHello;

/** Reads a world file into its {@link WorldElement}, reporting XML-level errors with their line. */
final class ElementReader {
    private static final String ROOT = "world";
    private static final XmlMapper MAPPER = mapper();
    /** The characters of a parser's message kept: the rule it names, with what it quotes of the file. */
    private static final int PARSER_MESSAGE_CHARS = 200;

    private ElementReader() {
    }

    private static XmlMapper mapper() {
        SimpleModule module = new SimpleModule("robosim-world");
        module.setDeserializerModifier(new LocatingDeserializer.Modifier());
        module.addDeserializer(String.class, new AttributeDeserializer());
        XmlMapper mapper = XmlMapper.builder()
                .visibility(PropertyAccessor.ALL, JsonAutoDetect.Visibility.NONE)
                .enable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES)
                .enable(DeserializationFeature.FAIL_ON_TRAILING_TOKENS)
                .addModule(module)
                .build();
        mapper.addHandler(new UnknownNodeHandler());
        return mapper;
    }

    /**
     * @param file the world file
     * @return its root element with its children
     * @throws WorldFileException if the file cannot be read, is not well-formed XML, is not a
     *                            world, or has an element or attribute the format does not know
     */
    static WorldElement read(Path file) {
        try (InputStream in = Files.newInputStream(file);
             FromXmlParser p = (FromXmlParser) MAPPER.getFactory().createParser(in)) {
            XMLStreamReader root = p.getStaxReader();
            if (!root.isStartElement() || !ROOT.equals(root.getLocalName())) {
                String found = root.isStartElement() ? "<" + LogLimiter.excerpt(root.getLocalName())
                        + ">" : "missing";
                throw new WorldFileException(file, root.getLocation().getLineNumber(),
                        "the root element is " + found + ", expected <" + ROOT + ">");
            }
            return MAPPER.readValue(p, WorldElement.class);
        } catch (XmlProblem problem) {
            throw new WorldFileException(file, problem.line, problem.rule, problem);
        } catch (NoSuchFileException e) {
            throw new WorldFileException(file, 0, "no such world file", e);
        } catch (JsonProcessingException e) {
            throw translate(file, e);
        } catch (IOException e) {
            throw new WorldFileException(file, 0, "cannot read the world file: " + e, e);
        }
    }

    private static WorldFileException translate(Path file, JsonProcessingException e) {
        for (Throwable t = e; t != null; t = t.getCause()) {
            if (t instanceof XmlProblem problem) {
                return new WorldFileException(file, problem.line, problem.rule, e);
            }
            if (t instanceof XMLStreamException xml) {
                Location at = xml.getLocation();
                return new WorldFileException(file, at == null ? 0 : at.getLineNumber(),
                        "malformed XML: " + firstLine(xml.getMessage()), e);
            }
        }
        JsonLocation at = e.getLocation();
        return new WorldFileException(file, at == null ? 0 : at.getLineNr(), firstLine(e.getOriginalMessage()), e);
    }

    /** @return the parser's first line, escaped and cut short: it may quote the file */
    private static String firstLine(String message) {
        String text = String.valueOf(message);
        int end = text.indexOf('\n');
        return RobotHello.printable((end < 0 ? text : text.substring(0, end)).trim(), PARSER_MESSAGE_CHARS);
    }
}

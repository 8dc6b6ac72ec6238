package robosim.protocol;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.core.StreamWriteConstraints;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ContainerNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import com.fasterxml.jackson.databind.node.POJONode;
import com.fasterxml.jackson.dataformat.smile.SmileFactory;
import com.fasterxml.jackson.dataformat.smile.SmileGenerator;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.math.BigDecimal;
import java.math.BigInteger;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Random;

/**
 * Mutates a message as a tree, the way a hostile or broken peer would write it: values of the wrong
 * type, numbers too large for their field, NaN and infinities, long strings, nesting deeper than
 * any message, fields removed, unknown or given twice, and type names swapped for other types'.
 * The tree is then written as JSON or Smile, nesting limits lifted, so that the codec's own limits
 * are what is tested.
 */
public final class PayloadMutator {
    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;
    private static final ObjectMapper TREES = new ObjectMapper();
    private static final StreamWriteConstraints UNLIMITED = StreamWriteConstraints.builder().maxNestingDepth(100_000).build();
    private static final JsonFactory JSON = JsonFactory.builder().streamWriteConstraints(UNLIMITED).build();
    private static final SmileFactory SMILE = SmileFactory.builder().streamWriteConstraints(UNLIMITED).build();
    /** Every message type and command name, so that a swapped name makes a known type of the wrong shape. */
    private static final List<String> TYPES = List.of("robotHello", "welcome", "timeStep", "robotRequests",
            "viewerHello", "world", "frame", "bye", "commsUpdate", "linkHello", "timeSteps", "linkRequests", "controlRequest", "controlReply", "vel",
            "rotVel", "vel2", "move", "heading", "deltaHeading", "stop", "maxVel", "maxRotVel", "sonar", "laser",
            "heatSensor", "send", "join", "leave", "found", "say", "moveWheels", "accel", "teleport", "", "Frame");

    private final Random random;

    /** @param random where the mutations come from */
    public PayloadMutator(Random random) {
        this.random = random;
    }

    /**
     * @param message a valid message
     * @param smile   whether to write Smile, else JSON
     * @return the message's tree, changed in one to three places, written as a payload
     */
    public byte[] mutate(Message message, boolean smile) {
        JsonNode root = TREES.valueToTree(message);
        for (int n = 1 + random.nextInt(3); n > 0; n--) {
            root = mutateOnce(root);
        }
        return write(root, smile);
    }

    private JsonNode mutateOnce(JsonNode root) {
        List<ContainerNode<?>> containers = new ArrayList<>();
        collect(root, containers);
        if (containers.isEmpty()) {
            return value();
        }
        ContainerNode<?> at = containers.get(random.nextInt(containers.size()));
        if (at instanceof ObjectNode o) {
            List<String> names = new ArrayList<>();
            o.fieldNames().forEachRemaining(names::add);
            String name = names.isEmpty() || random.nextInt(6) == 0 ? "extra" + random.nextInt(3)
                    : names.get(random.nextInt(names.size()));
            switch (random.nextInt(5)) {
                case 0 -> o.remove(name);
                case 1 -> o.put(name, TYPES.get(random.nextInt(TYPES.size())));
                default -> o.set(name, value());
            }
        } else if (at instanceof ArrayNode a) {
            if (a.isEmpty() || random.nextBoolean()) {
                a.add(value());
            } else {
                a.set(random.nextInt(a.size()), value());
            }
        }
        return random.nextInt(30) == 0 ? value() : root;
    }

    private static void collect(JsonNode node, List<ContainerNode<?>> into) {
        if (node instanceof ContainerNode<?> c) {
            into.add(c);
            node.elements().forEachRemaining(child -> collect(child, into));
        }
    }

    /** @return a value of any type, often one at the edge of what its type holds */
    private JsonNode value() {
        return switch (random.nextInt(16)) {
            case 0 -> NODES.numberNode(new BigInteger(1 + random.nextInt(300), random));
            case 1 -> NODES.numberNode(new BigDecimal("1e" + (random.nextInt(800) - 400)));
            case 2 -> NODES.numberNode(new double[] {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY,
                -0.0, Double.MAX_VALUE, Double.MIN_VALUE}[random.nextInt(6)]);
            case 3 -> NODES.numberNode(new long[] {Long.MAX_VALUE, Long.MIN_VALUE, Integer.MAX_VALUE + 1L,
                Integer.MIN_VALUE - 1L, -1}[random.nextInt(5)]);
            case 4 -> NODES.textNode("x".repeat(random.nextInt(4) == 0 ? 20_000 : random.nextInt(2000)));
            case 5 -> NODES.textNode(new String[] {"", "NaN", "Infinity", "12", "-0", "true", "null", "\u0000\n\"",
                "\ud800", "ROBOT", "GROUP"}[random.nextInt(11)]);
            case 6 -> NODES.nullNode();
            case 7 -> NODES.booleanNode(random.nextBoolean());
            case 8 -> NODES.arrayNode();
            case 9 -> NODES.objectNode();
            case 10 -> nested(random.nextInt(4) == 0 ? 2000 : random.nextInt(50));
            case 11 -> NODES.binaryNode(new byte[random.nextInt(64)]);
            case 12 -> {
                ObjectNode o = NODES.objectNode();
                o.put(random.nextBoolean() ? "type" : "cmd", TYPES.get(random.nextInt(TYPES.size())));
                yield o;
            }
            case 13 -> {
                ArrayNode a = NODES.arrayNode();
                for (int i = random.nextInt(4) == 0 ? 5_000 : random.nextInt(20); i > 0; i--) {
                    a.add(random.nextInt());
                }
                yield a;
            }
            default -> NODES.numberNode(random.nextInt());
        };
    }

    /**
     * UTF-8 as an encoder that does not check would write it: a lone surrogate in its 3-byte form,
     * which is not UTF-8 (Jackson's Smile generator refuses to write one, a hostile peer need not).
     */
    private static byte[] utf8(String text) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        for (int i = 0; i < text.length(); ) {
            int cp = text.codePointAt(i);
            i += Character.charCount(cp);
            if (cp < 0x80) {
                out.write(cp);
            } else if (cp < 0x800) {
                out.write(0xc0 | cp >> 6);
                out.write(0x80 | cp & 0x3f);
            } else if (cp < 0x10000) {
                out.write(0xe0 | cp >> 12);
                out.write(0x80 | cp >> 6 & 0x3f);
                out.write(0x80 | cp & 0x3f);
            } else {
                out.write(0xf0 | cp >> 18);
                out.write(0x80 | cp >> 12 & 0x3f);
                out.write(0x80 | cp >> 6 & 0x3f);
                out.write(0x80 | cp & 0x3f);
            }
        }
        return out.toByteArray();
    }

    /** Nesting, written without recursion when the tree is written (a deep tree would overflow the test's stack). */
    private record Nesting(int depth, long pattern) { }

    private JsonNode nested(int depth) {
        return NODES.pojoNode(new Nesting(depth, random.nextLong()));
    }

    /** Arrays and objects (each holding its child as "type") in turns of the pattern's bits, a number innermost. */
    private static void write(JsonGenerator g, Nesting n) throws IOException {
        for (int i = 0; i < n.depth(); i++) {
            if ((n.pattern() >>> (i % 64) & 1) == 0) {
                g.writeStartArray();
            } else {
                g.writeStartObject();
                g.writeFieldName("type");
            }
        }
        g.writeNumber(1);
        for (int i = n.depth() - 1; i >= 0; i--) {
            if ((n.pattern() >>> (i % 64) & 1) == 0) {
                g.writeEndArray();
            } else {
                g.writeEndObject();
            }
        }
    }

    private byte[] write(JsonNode root, boolean smile) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try (JsonGenerator g = smile ? SMILE.createGenerator(out) : JSON.createGenerator(out)) {
            write(g, root);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return out.toByteArray();
    }

    /** Writes a tree, now and then giving an object's field twice (a tree cannot hold that). */
    private void write(JsonGenerator g, JsonNode node) throws IOException {
        if (node instanceof ObjectNode o) {
            g.writeStartObject();
            for (Iterator<Map.Entry<String, JsonNode>> it = o.fields(); it.hasNext(); ) {
                Map.Entry<String, JsonNode> field = it.next();
                g.writeFieldName(field.getKey());
                write(g, field.getValue());
                if (random.nextInt(40) == 0) {
                    g.writeFieldName(field.getKey());
                    write(g, random.nextBoolean() ? field.getValue() : value());
                }
            }
            g.writeEndObject();
        } else if (node instanceof ArrayNode a) {
            g.writeStartArray();
            for (JsonNode element : a) {
                write(g, element);
            }
            g.writeEndArray();
        } else if (node instanceof POJONode p && p.getPojo() instanceof Nesting n) {
            write(g, n);
        } else if (node.isTextual() && g instanceof SmileGenerator) {
            byte[] utf8 = utf8(node.textValue());
            g.writeUTF8String(utf8, 0, utf8.length);
        } else {
            TREES.writeTree(g, node);
        }
    }
}

package robosim.viewer.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import robosim.protocol.Bye;
import robosim.protocol.FrameWriter;
import robosim.protocol.ViewerHello;
import robosim.protocol.WorldDescription;
import robosim.viewer.draw.ImageSink;
import robosim.viewer.draw.PngImageWriter;
import robosim.viewer.draw.RenderOptions;
import robosim.viewer.draw.Fixtures;
import robosim.viewer.draw.RenderedImages;
import robosim.viewer.draw.WorldRenderer;
import robosim.protocol.recording.SnapshotListener;

@Timeout(value = 30, unit = TimeUnit.SECONDS)
class ViewerClientTest {
    @TempDir
    Path tmp;

    private static ViewerOptions options(int port) {
        return ViewerOptions.of("127.0.0.1", port).withName("test-viewer")
                .withConnectTimeout(Duration.ofSeconds(5)).withReadTimeout(Duration.ofSeconds(5));
    }

    /** Draws every {@code every}-th snapshot, and the last, into the PNG writer. */
    private static List<SnapshotListener> drawing(ImageSink sink, int every) {
        return List.of(RenderedImages.flat(sink, new RenderOptions(400, true, true), every));
    }

    private static void worldThenTenSnapshots(FrameWriter out) throws IOException {
        out.write(Fixtures.world());
        for (int step = 1; step <= 10; step++) {
            out.write(Fixtures.snapshot(step, Fixtures.robot(1000 + 100 * step, 1500, 0, false, true)));
        }
    }

    private static List<String> files(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @ParameterizedTest(name = "every {0} writes {1} images")
    @CsvSource({"1, 10", "3, 4", "5, 2", "20, 1"})
    void writesEveryKthImageAndAlwaysTheLast(int every, int expected) throws Exception {
        try (FakeEnvironment env = new FakeEnvironment((out, socket) -> {
            worldThenTenSnapshots(out);
            out.write(new Bye("done"));
        })) {
            PngImageWriter png = new PngImageWriter(tmp.resolve("frames"));
            ViewerSummary summary = new ViewerClient(options(env.port()), drawing(png, every)).run();

            assertEquals(new ViewerSummary("fixture", 10, 10, "done"), summary);
            assertEquals(expected, png.imagesWritten());
            assertEquals(expected, files(png.directory()).size());
            assertTrue(Files.exists(png.fileFor(10)), "the last image is always written");
            assertEquals(new ViewerHello("test-viewer"), env.hello());
            assertNull(env.failure());
        }
    }

    @Test
    void imagesWrittenAtThreeAreTheMultiplesOfThreeAndTheLast() throws Exception {
        try (FakeEnvironment env = new FakeEnvironment((out, socket) -> {
            worldThenTenSnapshots(out);
            out.write(new Bye("done"));
        })) {
            PngImageWriter png = new PngImageWriter(tmp);
            new ViewerClient(options(env.port()), drawing(png, 3)).run();
            assertEquals(List.of("frame-000003.png", "frame-000006.png", "frame-000009.png", "frame-000010.png"),
                    files(tmp));
            BufferedImage image = ImageIO.read(png.fileFor(6).toFile());
            assertEquals(400, image.getWidth());
            assertEquals(200 + WorldRenderer.keyHeight(Fixtures.world(), new RenderOptions(400, true, true), 400),
                    image.getHeight(), "the world and the key under it");
        }
    }

    @Test
    void endOfStreamWithoutByeEndsTheRunAndKeepsTheLastImage() throws Exception {
        try (FakeEnvironment env = new FakeEnvironment((out, socket) -> {
            worldThenTenSnapshots(out);
            socket.shutdownOutput();
        })) {
            PngImageWriter png = new PngImageWriter(tmp);
            ViewerSummary summary = new ViewerClient(options(env.port()), drawing(png, 4)).run();
            assertEquals(new ViewerSummary("fixture", 10, 10, "end of stream"), summary);
            assertEquals(3, png.imagesWritten());
        }
    }

    @Test
    void reloadedWorldKeepsTheOldWorldsLastImage() throws Exception {
        try (FakeEnvironment env = new FakeEnvironment((out, socket) -> {
            out.write(Fixtures.world());
            for (int step = 1; step <= 3; step++) {
                out.write(Fixtures.snapshot(step, Fixtures.robotAtRest()));
            }
            out.write(new WorldDescription("reloaded", 2000, 2000, 100, List.of(), List.of()));
            out.write(Fixtures.snapshot(1, Fixtures.robot(1000, 1000, 0, false, true)));
            out.write(Fixtures.snapshot(2, Fixtures.robot(1100, 1000, 0, false, true)));
            out.write(new Bye("done"));
        })) {
            PngImageWriter png = new PngImageWriter(tmp);
            ViewerSummary summary = new ViewerClient(options(env.port()), drawing(png, 10)).run();
            assertEquals(new ViewerSummary("reloaded", 5, 2, "done"), summary);
            assertEquals(2, png.imagesWritten());
            assertEquals(List.of("frame-000002.png", "frame-000003.png"), files(tmp));
            WorldDescription square = new WorldDescription("reloaded", 2000, 2000, 100, List.of(), List.of());
            assertEquals(400 + WorldRenderer.keyHeight(square, new RenderOptions(400, true, true), 400),
                    ImageIO.read(png.fileFor(2).toFile()).getHeight(), "drawn with the square world");
        }
    }

    @Test
    void aWorldThatCannotBeDrawnStopsTheRunNamingIt() throws Exception {
        try (FakeEnvironment env = new FakeEnvironment((out, socket) -> {
            out.write(new WorldDescription("flat", 5000, 0, 100, List.of(), List.of()));
            out.write(new Bye("done"));
        })) {
            ViewerException e = assertThrows(ViewerException.class,
                    () -> new ViewerClient(options(env.port()), drawing(new PngImageWriter(tmp), 1)).run());
            assertEquals("the environment at 127.0.0.1:" + env.port() + " sent world 'flat', which a listener cannot"
                    + " take: the world cannot be drawn: world 'flat' has height 0.0 mm: height must be greater"
                    + " than 0 and finite", e.getMessage());
        }
    }

    @Test
    void hugeLengthPrefixFailsNamingThePeerInsteadOfHanging() throws Exception {
        try (FakeEnvironment env = new FakeEnvironment((out, socket) -> {
            socket.getOutputStream().write(new byte[] {(byte) 0xff, (byte) 0xff, (byte) 0xff, (byte) 0xff, 1, 2, 3});
        })) {
            ViewerException e = assertThrows(ViewerException.class,
                    () -> new ViewerClient(options(env.port()), drawing(new PngImageWriter(tmp), 1)).run());
            // The prefix is the viewer's; the reason after it is the protocol module's wording.
            assertTrue(e.getMessage().startsWith("the environment at 127.0.0.1:" + env.port()
                    + " broke the protocol: "), e.getMessage());
            assertTrue(e.getMessage().contains("4294967295"), e.getMessage());
        }
    }

    @Test
    void frameCutShortFailsWithTheReason() throws Exception {
        try (FakeEnvironment env = new FakeEnvironment((out, socket) -> {
            out.write(Fixtures.world());
            out.write(Fixtures.snapshot(1, Fixtures.robotAtRest()));
            socket.getOutputStream().write(new byte[] {0, 0, 3, (byte) 0xe8, 9, 9, 9});
            socket.shutdownOutput();
        })) {
            ViewerException e = assertThrows(ViewerException.class,
                    () -> new ViewerClient(options(env.port()), drawing(new PngImageWriter(tmp), 1)).run());
            assertTrue(e.getMessage().startsWith("the environment at 127.0.0.1:" + env.port()
                    + " broke the protocol after step 1: "), e.getMessage());
            assertTrue(e.getMessage().contains("1000 bytes"), e.getMessage());
        }
    }

    @Test
    void firstMessageOtherThanTheWorldIsAProtocolError() throws Exception {
        try (FakeEnvironment env = new FakeEnvironment((out, socket) -> out.write(Fixtures.snapshot(1)))) {
            ViewerException e = assertThrows(ViewerException.class,
                    () -> new ViewerClient(options(env.port()), drawing(new PngImageWriter(tmp), 1)).run());
            assertEquals("the environment at 127.0.0.1:" + env.port() + " broke the protocol: the first message "
                    + "must be a world description, not Snapshot", e.getMessage());
        }
    }

    @Test
    void silentEnvironmentTimesOutWithinTheReadTimeout() throws Exception {
        // A length prefix promising 1000 bytes, then nothing: the reader waits inside a frame.
        try (FakeEnvironment env = new FakeEnvironment((out, socket) -> {
            out.write(Fixtures.world());
            socket.getOutputStream().write(new byte[] {0, 0, 3, (byte) 0xe8});
        })) {
            long start = System.nanoTime();
            ViewerException e = assertThrows(ViewerException.class, () -> new ViewerClient(
                    options(env.port()).withReadTimeout(Duration.ofMillis(300)), drawing(new PngImageWriter(tmp), 1)).run());
            long elapsedMs = (System.nanoTime() - start) / 1_000_000;
            assertEquals("the environment at 127.0.0.1:" + env.port() + " sent nothing for 300 ms (readTimeout) "
                    + "while the viewer waited for a frame", e.getMessage());
            assertTrue(elapsedMs < 3_000, "gave up after " + elapsedMs + " ms");
        }
    }

    @Test
    void refusedConnectionNamesThePeer() throws Exception {
        int port;
        try (ServerSocket closed = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            port = closed.getLocalPort();
        }
        ViewerException e = assertThrows(ViewerException.class,
                () -> new ViewerClient(options(port), drawing(new PngImageWriter(tmp), 1)).run());
        assertTrue(e.getMessage().startsWith("cannot connect to the environment at 127.0.0.1:" + port + ": "),
                e.getMessage());
    }

    @Test
    void failingSinkStopsTheRunNamingTheStep() throws Exception {
        try (FakeEnvironment env = new FakeEnvironment((out, socket) -> {
            worldThenTenSnapshots(out);
            out.write(new Bye("done"));
        })) {
            ImageSink full = (step, image) -> {
                throw new IOException("disk full");
            };
            ViewerException e = assertThrows(ViewerException.class,
                    () -> new ViewerClient(options(env.port()), drawing(full, 2)).run());
            assertEquals("cannot store the frame of step 2 from 127.0.0.1:" + env.port() + ": disk full",
                    e.getMessage());
        }
    }

    @Test
    void optionsNameTheBadValue() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> RenderedImages.requireEvery(0));
        assertEquals("0 was supplied for every: every must be at least 1", e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> ViewerOptions.of("localhost", 0));
        assertEquals("0 was supplied for port: port must be from 1 to 65535", e.getMessage());
    }
}

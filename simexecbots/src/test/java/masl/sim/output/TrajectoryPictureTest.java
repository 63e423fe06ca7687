package masl.sim.output;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;

/** The top-down picture shows the robots' paths, not a blank or uniform image. */
class TrajectoryPictureTest {

    /** Two robots: one drives a quarter circle, one a straight line; a wall between them. */
    private static List<RunRecorder.Sample> samples() {
        List<RunRecorder.Sample> samples = new java.util.ArrayList<>();
        for (int i = 0; i <= 50; i++) {
            double t = i * 0.1;
            double angle = Math.PI / 2 * i / 50;
            samples.add(new RunRecorder.Sample(t, "k0", Math.cos(angle) - 0.5, Math.sin(angle) - 0.5, 0.03, angle + Math.PI / 2));
            samples.add(new RunRecorder.Sample(t, "k1", -0.5 + i * 0.02, -0.8, 0.03, 0));
        }
        return samples;
    }

    private static int count(BufferedImage image, Color colour) {
        int found = 0;
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                if ((image.getRGB(x, y) & 0xffffff) == (colour.getRGB() & 0xffffff)) {
                    found++;
                }
            }
        }
        return found;
    }

    @Test
    void pathsObstaclesAndEventsAreDrawnInTheirColours() throws Exception {
        List<double[][]> wall = List.<double[][]>of(new double[][] {{0.2, -0.7}, {0.3, -0.7}, {0.3, 0.2}, {0.2, 0.2}});
        List<RunRecorder.Event> events = List.of(new RunRecorder.Event(2.5, "k1", "fault", ""));
        Path file = Files.createDirectories(Path.of("build", "pictures")).resolve("picture-test.png");
        new TrajectoryPicture(600).write(file, "picture test", samples(), events, wall);

        BufferedImage image = ImageIO.read(file.toFile());
        assertEquals(600, image.getWidth());
        int white = count(image, Color.WHITE);
        assertTrue(white < 0.97 * 600 * 600, "not blank: " + white + " white pixels");
        assertTrue(white > 0.5 * 600 * 600, "mostly background, not a uniform fill");
        // A quarter circle of radius 1 m at about 0.45 px/mm is hundreds of pixels long, 2.5 px wide.
        assertTrue(count(image, TrajectoryPicture.PALETTE[0]) > 500, "k0's path drawn");
        assertTrue(count(image, TrajectoryPicture.PALETTE[1]) > 300, "k1's path drawn");
        assertTrue(count(image, new Color(0xb0b0b0)) > 1000, "the wall drawn");
        assertTrue(count(image, new Color(0xd62728)) > 5, "the fault marked");
    }

    /** The legend under the picture, right of the scale bar: the marks it explains, and no others. */
    @Test
    void aLegendExplainsTheMarksOfThePicture() throws Exception {
        List<double[][]> wall = List.<double[][]>of(new double[][] {{0.2, -0.7}, {0.3, -0.7}, {0.3, 0.2}, {0.2, 0.2}});
        List<RunRecorder.Event> events = List.of(new RunRecorder.Event(2.5, "k1", "fault", ""));
        BufferedImage all = new TrajectoryPicture(600).draw("legend", samples(), events, wall);
        ImageIO.write(all, "png", Files.createDirectories(Path.of("build", "pictures")).resolve("legend-test.png").toFile());
        BufferedImage legend = all.getSubimage(300, 600 - 50, 300, 50);
        assertTrue(count(legend, Color.BLACK) > 100, "the start and end marks and their words");
        assertTrue(count(legend, new Color(0xd62728)) > 5, "the event's cross");
        assertTrue(count(legend, new Color(0xb0b0b0)) > 100, "the obstacle's square");

        BufferedImage plain = new TrajectoryPicture(600).draw("legend", samples(), List.of(), List.of())
                .getSubimage(300, 600 - 50, 300, 50);
        assertTrue(count(plain, Color.BLACK) > 100, "start and end are always explained");
        assertEquals(0, count(plain, new Color(0xd62728)), "no event, no event in the legend");
        assertEquals(0, count(plain, new Color(0xb0b0b0)), "no obstacle, no obstacle in the legend");
    }

    @Test
    void anEmptyRunGivesAnImageWithAGridOnly() {
        BufferedImage image = new TrajectoryPicture(300).draw("empty", List.of(), List.of(), List.of());
        assertEquals(0, count(image, TrajectoryPicture.PALETTE[0]));
        assertTrue(count(image, Color.WHITE) > 0.8 * 300 * 300);
    }
}

package masl.sim.output;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Path2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import javax.imageio.ImageIO;

/**
 * Draws a run seen from above as a PNG (Java2D, headless): a metre grid with a scale bar, the
 * static boxes of the world in grey, and each robot's trajectory in its own colour from a hollow
 * circle (start) to a filled circle with a heading tick (end), labelled with its name; events are
 * red crosses where the robot was at the time. A legend under the picture, beside the scale bar,
 * says what each mark means (events and obstacles only when there are some). World +X points right
 * and +Y up.
 */
public final class TrajectoryPicture {

    /** Distinct colours for up to ten robots, then repeated. */
    static final Color[] PALETTE = {
        new Color(0x1f77b4), new Color(0xff7f0e), new Color(0x2ca02c), new Color(0x9467bd), new Color(0x8c564b),
        new Color(0xe377c2), new Color(0x17becf), new Color(0xbcbd22), new Color(0x7f7f7f), new Color(0x393b79)};
    private static final Color GRID = new Color(0xe6e6e6);
    private static final Color OBSTACLE = new Color(0xb0b0b0);
    private static final Color EVENT = new Color(0xd62728);
    private static final int MARGIN = 50;

    private final int size;

    /** The colour of the {@code index}-th robot's path (robots in the order of their first sample). */
    public static Color colour(int index) {
        return PALETTE[index % PALETTE.length];
    }

    /** @param size the picture's width and height in pixels, at least 200 */
    public TrajectoryPicture(int size) {
        if (size < 200) {
            throw new IllegalArgumentException("size: " + size);
        }
        this.size = size;
    }

    /** Draws the run into an image. */
    public BufferedImage draw(String title, List<RunRecorder.Sample> samples, List<RunRecorder.Event> events,
            List<double[][]> obstacles) {
        Map<String, List<RunRecorder.Sample>> paths = new LinkedHashMap<>();
        samples.forEach(s -> paths.computeIfAbsent(s.agent(), a -> new ArrayList<>()).add(s));
        Frame frame = Frame.around(samples, obstacles, size);

        BufferedImage image = new BufferedImage(size, size, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setColor(Color.WHITE);
            g.fillRect(0, 0, size, size);
            drawGrid(g, frame);
            g.setColor(OBSTACLE);
            for (double[][] outline : obstacles) {
                Path2D.Double shape = new Path2D.Double();
                shape.moveTo(frame.px(outline[0][0]), frame.py(outline[0][1]));
                for (int i = 1; i < outline.length; i++) {
                    shape.lineTo(frame.px(outline[i][0]), frame.py(outline[i][1]));
                }
                shape.closePath();
                g.fill(shape);
            }
            int index = 0;
            for (Map.Entry<String, List<RunRecorder.Sample>> path : paths.entrySet()) {
                drawPath(g, frame, path.getKey(), path.getValue(), PALETTE[index++ % PALETTE.length]);
            }
            drawEvents(g, frame, events, paths);
            drawLegend(g, !events.isEmpty(), !obstacles.isEmpty());
            g.setColor(Color.BLACK);
            g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 14));
            g.drawString(title, MARGIN, 25);
        } finally {
            g.dispose();
        }
        return image;
    }

    /** Draws the run and writes it to {@code file} as PNG. */
    public void write(Path file, String title, List<RunRecorder.Sample> samples, List<RunRecorder.Event> events,
            List<double[][]> obstacles) throws IOException {
        if (!ImageIO.write(draw(title, samples, events, obstacles), "png", file.toFile())) {
            throw new IOException("no PNG writer in this JDK");
        }
    }

    private void drawGrid(Graphics2D g, Frame frame) {
        double spacing = frame.gridSpacing();
        g.setStroke(new BasicStroke(1));
        g.setColor(GRID);
        for (double x = Math.ceil(frame.minX / spacing) * spacing; x <= frame.maxX; x += spacing) {
            g.drawLine((int) frame.px(x), MARGIN, (int) frame.px(x), size - MARGIN);
        }
        for (double y = Math.ceil(frame.minY / spacing) * spacing; y <= frame.maxY; y += spacing) {
            g.drawLine(MARGIN, (int) frame.py(y), size - MARGIN, (int) frame.py(y));
        }
        int bar = (int) Math.round(spacing * frame.scale);
        g.setColor(Color.BLACK);
        g.setStroke(new BasicStroke(2));
        int y = size - MARGIN / 2;
        g.drawLine(MARGIN, y, MARGIN + bar, y);
        g.drawLine(MARGIN, y - 4, MARGIN, y + 4);
        g.drawLine(MARGIN + bar, y - 4, MARGIN + bar, y + 4);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        g.drawString(String.format(Locale.ROOT, "%s m", trim(spacing)), MARGIN + bar + 8, y + 4);
    }

    private static void drawPath(Graphics2D g, Frame frame, String agent, List<RunRecorder.Sample> path, Color colour) {
        g.setColor(colour);
        g.setStroke(new BasicStroke(2.5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        Path2D.Double line = new Path2D.Double();
        line.moveTo(frame.px(path.get(0).x()), frame.py(path.get(0).y()));
        for (RunRecorder.Sample s : path) {
            line.lineTo(frame.px(s.x()), frame.py(s.y()));
        }
        g.draw(line);
        RunRecorder.Sample start = path.get(0);
        RunRecorder.Sample end = path.get(path.size() - 1);
        g.setStroke(new BasicStroke(2));
        g.drawOval((int) frame.px(start.x()) - 6, (int) frame.py(start.y()) - 6, 12, 12);
        int ex = (int) frame.px(end.x());
        int ey = (int) frame.py(end.y());
        g.fillOval(ex - 6, ey - 6, 12, 12);
        g.drawLine(ex, ey, ex + (int) Math.round(14 * Math.cos(end.heading())), ey - (int) Math.round(14 * Math.sin(end.heading())));
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 12));
        g.drawString(agent, ex + 9, ey - 9);
    }

    private static void drawEvents(Graphics2D g, Frame frame, List<RunRecorder.Event> events,
            Map<String, List<RunRecorder.Sample>> paths) {
        g.setColor(EVENT);
        g.setStroke(new BasicStroke(2.5f));
        for (RunRecorder.Event event : events) {
            List<RunRecorder.Sample> path = paths.get(event.agent());
            if (path == null) {
                continue;
            }
            RunRecorder.Sample at = path.stream()
                    .min((a, b) -> Double.compare(Math.abs(a.time() - event.time()), Math.abs(b.time() - event.time())))
                    .orElseThrow();
            int x = (int) frame.px(at.x());
            int y = (int) frame.py(at.y());
            g.drawLine(x - 6, y - 6, x + 6, y + 6);
            g.drawLine(x - 6, y + 6, x + 6, y - 6);
        }
    }

    /** The marks of the legend, each drawn as in the picture, centred on ({@code x}, {@code y}). */
    private enum Mark {
        START("start"), END("end, heading"), EVENT("event"), OBSTACLE("obstacle");

        final String meaning;

        Mark(String meaning) {
            this.meaning = meaning;
        }

        void draw(Graphics2D g, int x, int y) {
            g.setStroke(new BasicStroke(2));
            switch (this) {
                case START -> {
                    g.setColor(Color.BLACK);
                    g.drawOval(x - 6, y - 6, 12, 12);
                }
                case END -> {
                    g.setColor(Color.BLACK);
                    g.fillOval(x - 6, y - 6, 12, 12);
                    g.drawLine(x, y, x + 10, y - 10);
                }
                case EVENT -> {
                    g.setColor(TrajectoryPicture.EVENT);
                    g.setStroke(new BasicStroke(2.5f));
                    g.drawLine(x - 6, y - 6, x + 6, y + 6);
                    g.drawLine(x - 6, y + 6, x + 6, y - 6);
                }
                case OBSTACLE -> {
                    g.setColor(TrajectoryPicture.OBSTACLE);
                    g.fillRect(x - 6, y - 6, 12, 12);
                }
            }
        }
    }

    /** The legend, right-aligned in the bottom margin, on the scale bar's line. */
    private void drawLegend(Graphics2D g, boolean events, boolean obstacles) {
        List<Mark> marks = new ArrayList<>(List.of(Mark.START, Mark.END));
        if (events) {
            marks.add(Mark.EVENT);
        }
        if (obstacles) {
            marks.add(Mark.OBSTACLE);
        }
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        FontMetrics metrics = g.getFontMetrics();
        int y = size - MARGIN / 2;
        int x = size - MARGIN;
        for (int i = marks.size() - 1; i >= 0; i--) {
            Mark mark = marks.get(i);
            int text = metrics.stringWidth(mark.meaning);
            x -= text;
            g.setColor(Color.BLACK);
            g.drawString(mark.meaning, x, y + 4);
            mark.draw(g, x - 12, y);
            x -= 12 + 6 + 16;
        }
    }

    private static String trim(double value) {
        return value == Math.rint(value) ? Long.toString((long) value) : Double.toString(value);
    }

    /** The world rectangle shown and its mapping to pixels (same scale on both axes). */
    private static final class Frame {
        final double minX;
        final double minY;
        final double maxX;
        final double maxY;
        final double scale;
        final int size;

        private Frame(double minX, double minY, double maxX, double maxY, int size) {
            double span = Math.max(Math.max(maxX - minX, maxY - minY), 0.2);
            double cx = (minX + maxX) / 2;
            double cy = (minY + maxY) / 2;
            this.minX = cx - span / 2;
            this.maxX = cx + span / 2;
            this.minY = cy - span / 2;
            this.maxY = cy + span / 2;
            this.size = size;
            this.scale = (size - 2.0 * MARGIN) / span;
        }

        static Frame around(List<RunRecorder.Sample> samples, List<double[][]> obstacles, int size) {
            double minX = Double.POSITIVE_INFINITY;
            double minY = Double.POSITIVE_INFINITY;
            double maxX = Double.NEGATIVE_INFINITY;
            double maxY = Double.NEGATIVE_INFINITY;
            for (RunRecorder.Sample s : samples) {
                minX = Math.min(minX, s.x());
                maxX = Math.max(maxX, s.x());
                minY = Math.min(minY, s.y());
                maxY = Math.max(maxY, s.y());
            }
            for (double[][] outline : obstacles) {
                for (double[] corner : outline) {
                    minX = Math.min(minX, corner[0]);
                    maxX = Math.max(maxX, corner[0]);
                    minY = Math.min(minY, corner[1]);
                    maxY = Math.max(maxY, corner[1]);
                }
            }
            if (minX > maxX) {
                return new Frame(-0.5, -0.5, 0.5, 0.5, size);
            }
            double pad = 0.05 * Math.max(maxX - minX, maxY - minY) + 0.05;
            return new Frame(minX - pad, minY - pad, maxX + pad, maxY + pad, size);
        }

        double px(double x) {
            return MARGIN + (x - minX) * scale;
        }

        double py(double y) {
            return size - MARGIN - (y - minY) * scale;
        }

        /** 1, 2 or 5 times a power of ten, giving about five to ten grid lines. */
        double gridSpacing() {
            double span = maxX - minX;
            double raw = span / 8;
            double power = Math.pow(10, Math.floor(Math.log10(raw)));
            for (double factor : new double[] {1, 2, 5, 10}) {
                if (factor * power >= raw) {
                    return factor * power;
                }
            }
            return 10 * power;
        }
    }
}

package org.jecosys.app;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.Iterator;
import java.util.List;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageTypeSpecifier;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.metadata.IIOMetadata;
import javax.imageio.metadata.IIOMetadataNode;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;
import org.jecosys.scene.OutputFiles;

/**
 * Assembles PNG frames into a looping animated GIF with the JDK's own GIF writer, written through
 * {@link OutputFiles} (atomic; never through a link, never onto a pipe or device). The frames are
 * read back without following links, and only while they are regular files. Any thread; allocates.
 */
final class GifWriter {
    private static final String FORMAT = "javax_imageio_gif_image_1.0";

    private GifWriter() {
    }

    /**
     * Writes {@code frames} (PNG files, all the same size) to {@code gif}, each shown for
     * {@code delayCentis} hundredths of a second, looping forever. Memory holds one frame at a time.
     *
     * @throws IOException naming the file when a frame cannot be read or the GIF cannot be written; the
     *                     GIF's previous file (or none) is then left as it was
     */
    static void write(List<Path> frames, Path gif, int delayCentis) throws IOException {
        if (frames.isEmpty()) {
            throw new IOException("no frames to put in " + gif);
        }
        Iterator<ImageWriter> it = ImageIO.getImageWritersBySuffix("gif");
        if (!it.hasNext()) {
            throw new IOException("this JVM has no GIF writer");
        }
        ImageWriter writer = it.next();
        try {
            new OutputFiles().write(gif, stream -> {
                ImageOutputStream out = new MemoryCacheImageOutputStream(stream);
                writer.setOutput(out);
                writer.prepareWriteSequence(null);
                ImageWriteParam param = writer.getDefaultWriteParam();
                boolean first = true;
                for (Path p : frames) {
                    writer.writeToSequence(frame(writer, param, readFrame(p), first, delayCentis), param);
                    out.flushBefore(out.getStreamPosition()); // the cache keeps one frame, not the whole GIF
                    first = false;
                }
                writer.endWriteSequence();
                out.flush();
                out.close(); // the cache only: the file's stream stays open for the writer to finish
            });
        } finally {
            writer.dispose();
        }
    }

    /** Reads a frame back, refusing anything that is no longer a regular file (never opens a pipe or a link). */
    private static BufferedImage readFrame(Path p) throws IOException {
        if (!Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS)) {
            throw new IOException("cannot read frame " + p + ": it is no longer a regular file");
        }
        BufferedImage src;
        try (InputStream in = Files.newInputStream(p, LinkOption.NOFOLLOW_LINKS)) {
            src = ImageIO.read(in);
        }
        if (src == null) {
            throw new IOException("cannot read frame " + p + ": not an image");
        }
        BufferedImage rgb = new BufferedImage(src.getWidth(), src.getHeight(), BufferedImage.TYPE_INT_RGB);
        rgb.getGraphics().drawImage(src, 0, 0, null);
        return rgb;
    }

    /** One frame with its delay; the first also carries the loop-forever extension. */
    private static IIOImage frame(ImageWriter writer, ImageWriteParam param, BufferedImage rgb, boolean first,
                                  int delayCentis) throws IOException {
        IIOMetadata meta = writer.getDefaultImageMetadata(ImageTypeSpecifier.createFromRenderedImage(rgb), param);
        IIOMetadataNode root = (IIOMetadataNode) meta.getAsTree(FORMAT);
        IIOMetadataNode gce = child(root, "GraphicControlExtension");
        gce.setAttribute("disposalMethod", "none");
        gce.setAttribute("userInputFlag", "FALSE");
        gce.setAttribute("transparentColorFlag", "FALSE");
        gce.setAttribute("delayTime", Integer.toString(delayCentis));
        gce.setAttribute("transparentColorIndex", "0");
        if (first) {
            IIOMetadataNode apps = child(root, "ApplicationExtensions");
            IIOMetadataNode app = new IIOMetadataNode("ApplicationExtension");
            app.setAttribute("applicationID", "NETSCAPE");
            app.setAttribute("authenticationCode", "2.0");
            app.setUserObject(new byte[] {1, 0, 0}); // loop forever
            apps.appendChild(app);
        }
        meta.setFromTree(FORMAT, root);
        return new IIOImage(rgb, null, meta);
    }

    private static IIOMetadataNode child(IIOMetadataNode root, String name) {
        for (int i = 0; i < root.getLength(); i++) {
            if (root.item(i).getNodeName().equalsIgnoreCase(name)) {
                return (IIOMetadataNode) root.item(i);
            }
        }
        IIOMetadataNode n = new IIOMetadataNode(name);
        root.appendChild(n);
        return n;
    }
}

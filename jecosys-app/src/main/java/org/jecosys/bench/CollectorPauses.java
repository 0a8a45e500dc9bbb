package org.jecosys.bench;

import com.sun.management.GarbageCollectionNotificationInfo;
import java.lang.management.GarbageCollectorMXBean;
import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.List;
import javax.management.ListenerNotFoundException;
import javax.management.Notification;
import javax.management.NotificationEmitter;
import javax.management.NotificationListener;
import javax.management.openmbean.CompositeData;

/**
 * The collector's pauses while a bench section runs, as a game would feel them: each pause's start and
 * length, from the JVM's collection notifications. Collectors that report their concurrent cycles
 * through a bean of their own (ZGC's and Shenandoah's "Cycles", G1's "Concurrent GC" on later JDKs) are
 * left out: those cycles run beside the application's threads. A notification gives a pause's start in
 * whole milliseconds on a clock of the JVM's own, whose origin the API does not give (it differs from
 * the runtime's uptime by tens of milliseconds); it arrives on the JVM's notification thread a little
 * after the pause ends. So the clock is set against System.nanoTime() by the notification that came
 * soonest after its pause's end (an arrival is never before the end): a pause is placed to within that
 * delay and the clock's two milliseconds. The readers see what arrived. Bench only: listening allocates
 * per collection, {@link #within} its result.
 */
final class CollectorPauses implements AutoCloseable {
    /** Pauses kept; later ones are not noted. */
    private static final int KEPT = 8192;
    private static final long MS = 1_000_000L;
    /** How well a pause is placed: the collector's clock's two whole milliseconds, nanoseconds. */
    private static final long SLACK = 2 * MS;
    /** Per pause, its start on the collector's clock, nanoseconds (whole milliseconds). */
    private final long[] clockStart = new long[KEPT];
    private final long[] lengthNanos = new long[KEPT];
    private int count;
    /** System.nanoTime() minus the collector's clock: the least of arrival minus pause end seen so far. */
    private long offset = Long.MAX_VALUE;
    private final List<NotificationEmitter> emitters = new ArrayList<>();
    private final NotificationListener listener = this::noted;

    /** Starts listening to every collector that pauses the application. Allocates. */
    CollectorPauses() {
        for (GarbageCollectorMXBean gc : ManagementFactory.getGarbageCollectorMXBeans()) {
            if (pauses(gc.getName()) && gc instanceof NotificationEmitter e) {
                e.addNotificationListener(listener, null, null);
                emitters.add(e);
            }
        }
    }

    /** {@return whether the collector bean named {@code name} reports pauses, not concurrent cycles} */
    static boolean pauses(String name) {
        return !name.contains("Cycles") && !name.contains("Concurrent");
    }

    /** {@return the names of this JVM's collectors that pause the application, joined by " and "} */
    static String names() {
        StringBuilder b = new StringBuilder();
        for (GarbageCollectorMXBean gc : ManagementFactory.getGarbageCollectorMXBeans()) {
            if (pauses(gc.getName())) {
                b.append(b.length() > 0 ? " and " : "").append(gc.getName());
            }
        }
        return b.toString();
    }

    private void noted(Notification n, Object handback) {
        if (!GarbageCollectionNotificationInfo.GARBAGE_COLLECTION_NOTIFICATION.equals(n.getType())) {
            return;
        }
        long arrived = System.nanoTime();
        var info = GarbageCollectionNotificationInfo.from((CompositeData) n.getUserData()).getGcInfo();
        add(info.getStartTime() * MS, info.getDuration() * MS, arrived);
    }

    /**
     * Notes a pause that began at {@code clockStart} on the collector's clock and lasted {@code length}
     * nanoseconds, whose notice arrived at {@code arrived} (System.nanoTime()).
     */
    synchronized void add(long clockStart, long length, long arrived) {
        offset = Math.min(offset, arrived - (clockStart + length));
        if (count < KEPT) {
            this.clockStart[count] = clockStart;
            lengthNanos[count] = length;
            count++;
        }
    }

    /** {@return pause i's start, System.nanoTime()} */
    private long start(int i) {
        return clockStart[i] + offset;
    }

    /** {@return the pauses noted so far (at most 8,192 are kept)} */
    synchronized int count() {
        return count;
    }

    /**
     * The pauses that began in [from, to] (System.nanoTime()), leaving out those that began within one of
     * the {@code skips} windows [skipFrom[k], skipTo[k]] (a collection the bench asked for itself), each
     * window widened by the two milliseconds a pause is placed to.
     *
     * @return {pauses, their lengths summed in milliseconds, the longest in milliseconds (0 when none)}
     */
    synchronized double[] within(long from, long to, long[] skipFrom, long[] skipTo, int skips) {
        int n = 0;
        long total = 0;
        long longest = 0;
        for (int i = 0; i < count; i++) {
            long s = start(i);
            boolean skipped = false;
            for (int k = 0; k < skips && !skipped; k++) {
                skipped = s >= skipFrom[k] - SLACK && s <= skipTo[k] + SLACK;
            }
            if (s >= from && s <= to && !skipped) {
                n++;
                total += lengthNanos[i];
                longest = Math.max(longest, lengthNanos[i]);
            }
        }
        return new double[] {n, total / 1e6, longest / 1e6};
    }

    /** {@return whether a pause overlaps [from, to] (System.nanoTime()), give or take two milliseconds} */
    synchronized boolean overlaps(long from, long to) {
        for (int i = 0; i < count; i++) {
            if (start(i) - SLACK <= to && start(i) + lengthNanos[i] + SLACK >= from) {
                return true;
            }
        }
        return false;
    }

    /** Stops listening. Idempotent. */
    @Override
    public void close() {
        for (NotificationEmitter e : emitters) {
            try {
                e.removeNotificationListener(listener);
            } catch (ListenerNotFoundException ex) {
                // already removed
            }
        }
        emitters.clear();
    }
}

package org.jecosys.terrain;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.IntConsumer;
import org.jecosys.math.Require;

/**
 * Runs fixed chunks of work on a small private thread pool (or inline for one thread). Chunks must
 * write disjoint outputs and derive any randomness from their chunk index, so results are identical
 * for every thread count (see docs/ARCHITECTURE.md, "Threads"). Owned and closed by the thread that
 * created it.
 */
final class Workers implements AutoCloseable {
    private final int threads;
    private final ExecutorService pool;

    Workers(int threads) {
        this.threads = Require.range("threads", threads, 1, 1024);
        this.pool = threads == 1 ? null : Executors.newFixedThreadPool(threads, r -> {
            Thread t = new Thread(r, "jecosys-terrain");
            t.setDaemon(true);
            return t;
        });
    }

    /** Runs {@code body.accept(c)} for every chunk c in [0, chunks) and returns when all are done. */
    void run(int chunks, IntConsumer body) {
        if (pool == null || chunks <= 1) {
            for (int c = 0; c < chunks; c++) {
                body.accept(c);
            }
            return;
        }
        AtomicInteger next = new AtomicInteger();
        int n = Math.min(threads, chunks);
        List<Future<?>> futures = new ArrayList<>(n);
        for (int t = 0; t < n; t++) {
            futures.add(pool.submit(() -> {
                for (int c = next.getAndIncrement(); c < chunks; c = next.getAndIncrement()) {
                    body.accept(c);
                }
            }));
        }
        for (Future<?> f : futures) {
            try {
                f.get();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("interrupted while waiting for terrain workers", e);
            } catch (ExecutionException e) {
                Throwable cause = e.getCause();
                if (cause instanceof RuntimeException re) {
                    throw re;
                }
                if (cause instanceof Error err) {
                    throw err;
                }
                throw new IllegalStateException(cause);
            }
        }
    }

    @Override
    public void close() {
        if (pool != null) {
            pool.shutdownNow();
        }
    }
}

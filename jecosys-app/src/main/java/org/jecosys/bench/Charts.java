package org.jecosys.bench;

import java.io.IOException;
import java.io.OutputStream;
import java.util.ArrayList;
import java.util.List;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.CategoryChart;
import org.knowm.xchart.CategoryChartBuilder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.style.Styler;

/** PNG charts of the report (XChart; no display needed), drawn into a stream. Any thread; allocates. */
public final class Charts {
    private static final int WIDTH = 900;
    private static final int HEIGHT = 520;

    private Charts() {
    }

    /**
     * A grouped bar chart of a table: one group per row (labelled by column {@code labelColumn}),
     * one bar series per column named in {@code valueColumns}; non-numeric cells count as 0.
     */
    public static void bars(Table table, int labelColumn, List<String> valueColumns, String yTitle, OutputStream png)
            throws IOException {
        CategoryChart chart = new CategoryChartBuilder().width(WIDTH).height(HEIGHT).title(table.title())
                .xAxisTitle(table.headers().get(labelColumn)).yAxisTitle(yTitle).build();
        style(chart.getStyler());
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNE);
        List<String> labels = new ArrayList<>();
        for (List<Object> r : table.rows()) {
            labels.add(String.valueOf(r.get(labelColumn)));
        }
        for (String col : valueColumns) {
            int c = table.headers().indexOf(col);
            if (c < 0) {
                throw new IllegalArgumentException("table " + table.id() + " has no column '" + col + "'");
            }
            List<Double> values = new ArrayList<>();
            for (List<Object> r : table.rows()) {
                Object v = r.get(c);
                values.add(v instanceof Number n && Double.isFinite(n.doubleValue()) ? n.doubleValue() : 0.0);
            }
            chart.addSeries(col, labels, values);
        }
        BitmapEncoder.saveBitmap(chart, png, BitmapEncoder.BitmapFormat.PNG);
    }

    /** A line chart with logarithmic axes when asked, one series per name. */
    public static void lines(String title, String xTitle, String yTitle, List<String> names, List<double[]> xs,
                             List<double[]> ys, boolean logX, boolean logY, OutputStream png) throws IOException {
        XYChart chart = new XYChartBuilder().width(WIDTH).height(HEIGHT).title(title).xAxisTitle(xTitle)
                .yAxisTitle(yTitle).build();
        style(chart.getStyler());
        chart.getStyler().setXAxisLogarithmic(logX);
        chart.getStyler().setYAxisLogarithmic(logY);
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNW);
        for (int i = 0; i < names.size(); i++) {
            chart.addSeries(names.get(i), xs.get(i), ys.get(i));
        }
        BitmapEncoder.saveBitmap(chart, png, BitmapEncoder.BitmapFormat.PNG);
    }

    private static void style(Styler s) {
        s.setChartBackgroundColor(java.awt.Color.WHITE);
        s.setAntiAlias(true);
    }
}

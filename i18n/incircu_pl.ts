<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="pl_PL">
<context>
    <name>IncirCuAlgorithm</name>
    <message>
        <location filename="../algorithms/base.py" line="158"/>
        <source>Centerlines</source>
        <translation>Linie środkowe</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="341"/>
        <source>Store the local width as M value</source>
        <translation>Zapisz lokalną szerokość jako wartość M</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="363"/>
        <source>Centerline vertices</source>
        <translation>Wierzchołki linii środkowej</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="363"/>
        <source>Incircles</source>
        <translation>Okręgi wpisane</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="363"/>
        <source>Transects</source>
        <translation>Przekroje poprzeczne</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="391"/>
        <source>Distance between transects (0 = mean width)</source>
        <translation>Odległość między przekrojami (0 = średnia szerokość)</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="401"/>
        <source>Number of centerlines</source>
        <translation>Liczba linii środkowych</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="401"/>
        <source>Number of centerline features written.</source>
        <translation>Liczba zapisanych obiektów linii środkowej.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="406"/>
        <source>Number of skipped features</source>
        <translation>Liczba pominiętych obiektów</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="406"/>
        <source>Number of input features (or parts) skipped with a warning.</source>
        <translation>Liczba obiektów wejściowych (lub ich części) pominiętych z ostrzeżeniem.</translation>
    </message>
    <message>
        <location filename="../algorithms/dependencies.py" line="49"/>
        <source>IncirCu needs the Python package Shapely 2, which is not installed.</source>
        <translation>IncirCu wymaga pakietu Pythona Shapely 2, który nie jest zainstalowany.</translation>
    </message>
    <message>
        <location filename="../algorithms/dependencies.py" line="58"/>
        <source>IncirCu needs Shapely 2.0 or newer, but Shapely {} is installed.</source>
        <translation>IncirCu wymaga Shapely 2.0 lub nowszego, a zainstalowany jest Shapely {}.</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="99"/>
        <source>{} must be a {} layer, but &apos;{}&apos; holds {} geometries.</source>
        <translation>{} musi być warstwą typu {}, a '{}' zawiera geometrie typu {}.</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="55"/>
        <source>the feature has no geometry</source>
        <translation>obiekt nie ma geometrii</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="191"/>
        <source>Feature {} skipped: {}</source>
        <translation>Obiekt {} pominięty: {}</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="199"/>
        <source>Feature {}: {}</source>
        <translation>Obiekt {}: {}</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="218"/>
        <source>{} (part {})</source>
        <translation>{} (część {})</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="242"/>
        <source>unexpected {}: {} (please report this with the feature)</source>
        <translation>nieoczekiwany błąd {}: {} (prosimy zgłosić go wraz z obiektem)</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="341"/>
        <source>Write the incircle diameter (local width, layer units or metres) as M value of each vertex.</source>
        <translation>Zapisz średnicę okręgu wpisanego (lokalną szerokość, w jednostkach warstwy lub metrach) jako wartość M każdego wierzchołka.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="363"/>
        <source>Optional point layer: every centerline vertex with its chainage, incircle radius and width.</source>
        <translation>Opcjonalna warstwa punktowa: każdy wierzchołek linii środkowej z kilometrażem, promieniem okręgu wpisanego i szerokością.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="363"/>
        <source>Optional polygon layer: the incircle of every vertex, with its radius and chainage.</source>
        <translation>Opcjonalna warstwa poligonowa: okrąg wpisany każdego wierzchołka z promieniem i kilometrażem.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="391"/>
        <source>Distance along the centerline between two transects, layer units (metres for a layer in degrees); 0 uses the mean width of each centerline.</source>
        <translation>Odległość wzdłuż linii środkowej między dwoma przekrojami, w jednostkach warstwy (w metrach dla warstwy w stopniach); 0 oznacza średnią szerokość każdej linii środkowej.</translation>
    </message>
    <message>
        <location filename="../algorithms/outputs.py" line="202"/>
        <source>Could not write a centerline: {}</source>
        <translation>Nie udało się zapisać linii środkowej: {}</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="363"/>
        <source>Optional line layer: cross-sections from bank to bank through the centerline, one every &apos;Distance between transects&apos;, with their width and chainage.</source>
        <translation>Opcjonalna warstwa liniowa: przekroje poprzeczne od brzegu do brzegu przez linię środkową, jeden co 'Odległość między przekrojami', z szerokością i kilometrażem.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="267"/>
        <source>Largest deviation from the exact medial axis (0 = automatic)</source>
        <translation>Największe odchylenie od dokładnej osi środkowej (0 = automatycznie)</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="278"/>
        <source>Fixed boundary sampling distance (0 = adaptive)</source>
        <translation>Stały odstęp próbkowania brzegu (0 = adaptacyjnie)</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="278"/>
        <source>The paper&apos;s fixed sampling: a sample every this distance along both sides, in layer units (metres for a layer in degrees), giving many evenly spaced vertices. Use it to reproduce the paper or for a dense line; 0 uses the adaptive sampling bounded by the largest deviation. Give either this or the largest deviation, not both.</source>
        <translation>Stałe próbkowanie z artykułu: próbka co tę odległość wzdłuż obu stron, w jednostkach warstwy (metry dla warstwy w stopniach), dające wiele równomiernie rozmieszczonych wierzchołków. Do odtworzenia artykułu lub gęstej linii; 0 oznacza próbkowanie adaptacyjne ograniczone największym odchyleniem. Podaj to albo największe odchylenie, nie oba.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="302"/>
        <source>Give either a largest deviation from the axis (adaptive sampling) or a fixed boundary sampling distance, not both; set the other one to 0.</source>
        <translation>Podaj największe odchylenie od osi (próbkowanie adaptacyjne) albo stały odstęp próbkowania brzegu, nie oba; ustaw drugie na 0.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="312"/>
        <source>Split point snapping tolerance</source>
        <translation>Tolerancja przyciągania punktów podziału</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="312"/>
        <source>Largest distance between a split point and the polygon&apos;s exterior ring, layer units (metres for a layer in degrees); 0 = a millionth of the polygon&apos;s size.</source>
        <translation>Największa odległość punktu podziału od zewnętrznego obrysu poligonu, w jednostkach warstwy (w metrach dla warstwy w stopniach); 0 = jedna milionowa rozmiaru poligonu.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="334"/>
        <source>Islands (holes)</source>
        <translation>Wyspy (otwory)</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="333"/>
        <source>Pass through the main channel</source>
        <translation>Prowadź głównym korytem</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="333"/>
        <source>Ignore islands</source>
        <translation>Pomijaj wyspy</translation>
    </message>
    <message>
        <location filename="../algorithms/network_outputs.py" line="91"/>
        <source>Could not write a branch: {}</source>
        <translation>Nie można zapisać gałęzi: {}</translation>
    </message>
    <message>
        <location filename="../algorithms/units.py" line="21"/>
        <source>layer units</source>
        <translation>jednostki warstwy</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="134"/>
        <source>{}: {} has no field &apos;{}&apos;; its fields are: {}.</source>
        <translation>{}: {} nie ma pola '{}'; jego pola to: {}.</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="134"/>
        <source>none</source>
        <translation>brak</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="196"/>
        <source>Parameters</source>
        <translation>Parametry</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="196"/>
        <source>Advanced parameters</source>
        <translation>Parametry zaawansowane</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="196"/>
        <source>Outputs</source>
        <translation>Wyniki</translation>
    </message>
    <message>
        <location filename="../algorithms/base.py" line="267"/>
        <source>Largest distance between the centerline and the exact medial axis, in layer units (metres for a layer in degrees): the line keeps only the vertices it needs to stay that close, each lying exactly on the axis, and never leaves the shape whatever the value. 0 uses 1/200 of the shape&apos;s typical width: the right choice for maps.</source>
        <translation>Największa odległość linii środkowej od dokładnej osi środkowej, w jednostkach warstwy (metry dla warstwy w stopniach): linia zachowuje tylko wierzchołki potrzebne, by pozostać tak blisko, każdy leżący dokładnie na osi, i nigdy nie wychodzi poza kształt, niezależnie od wartości. 0 oznacza 1/200 typowej szerokości kształtu: właściwy wybór dla map.</translation>
    </message>
    <message>
        <location filename="../algorithms/running.py" line="118"/>
        <source>Z values are ignored: &apos;{}&apos; has Z, but the centerline is computed in the plane and written without Z (its M values, when stored, are the local width).</source>
        <translation>Wartości Z są pomijane: '{}' ma współrzędną Z, ale linia środkowa jest obliczana na płaszczyźnie i zapisywana bez Z (jej wartości M, jeśli są zapisywane, to lokalna szerokość).</translation>
    </message>
    <message>
        <location filename="../algorithms/label_outputs.py" line="78"/>
        <source>Could not write a label: {}</source>
        <translation>Nie można zapisać etykiety: {}</translation>
    </message>
</context>
<context>
    <name>IncirCuExpressions</name>
    <message>
        <location filename="../algorithms/expressions.py" line="259"/>
        <source>{} must be a number, not {!r}</source>
        <translation>{} musi być liczbą, a nie {!r}</translation>
    </message>
    <message>
        <location filename="../algorithms/expressions.py" line="268"/>
        <source>end_rule must be one of {}, not {!r}</source>
        <translation>end_rule musi być jednym z: {}, a nie {!r}</translation>
    </message>
    <message>
        <location filename="../algorithms/expressions.py" line="300"/>
        <source>&lt;h3&gt;incircu_centerline(geometry, tolerance, end_rule)&lt;/h3&gt;&lt;p&gt;The centerline of every part of a polygon (IncirCu&apos;s Curve of Incircles, between automatic ends), as a multi-line in the layer&apos;s CRS; NULL when no part has one. For a geometry generator symbol.&lt;/p&gt;&lt;h4&gt;Arguments&lt;/h4&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;geometry&lt;/b&gt;: a polygon, usually &lt;code&gt;$geometry&lt;/code&gt;.&lt;/li&gt;&lt;li&gt;&lt;b&gt;tolerance&lt;/b&gt; (optional): largest distance from the exact medial axis, layer units (metres for a layer in degrees); 0 or NULL: 1/200 of the typical width.&lt;/li&gt;&lt;li&gt;&lt;b&gt;end_rule&lt;/b&gt; (optional): &apos;main_stem&apos; (default) or &apos;longest_path&apos;.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Results are cached per geometry: panning and zooming do not recompute them.&lt;/p&gt;&lt;h4&gt;Example&lt;/h4&gt;&lt;p&gt;&lt;code&gt;incircu_centerline($geometry)&lt;/code&gt;&lt;/p&gt;</source>
        <translation>&lt;h3&gt;incircu_centerline(geometry, tolerance, end_rule)&lt;/h3&gt;&lt;p&gt;Linia środkowa każdej części poligonu (krzywa okręgów wpisanych IncirCu, między automatycznymi końcami) jako wielolinia w układzie warstwy; NULL, gdy żadna część jej nie ma. Do symbolu z generatorem geometrii.&lt;/p&gt;&lt;h4&gt;Argumenty&lt;/h4&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;geometry&lt;/b&gt;: poligon, zwykle &lt;code&gt;$geometry&lt;/code&gt;.&lt;/li&gt;&lt;li&gt;&lt;b&gt;tolerance&lt;/b&gt; (opcjonalny): największa odległość od dokładnej osi środkowej w jednostkach warstwy (w metrach dla warstwy w stopniach); 0 lub NULL: 1/200 typowej szerokości.&lt;/li&gt;&lt;li&gt;&lt;b&gt;end_rule&lt;/b&gt; (opcjonalny): 'main_stem' (domyślnie) lub 'longest_path'.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Wyniki są zapamiętywane dla każdej geometrii: przesuwanie i powiększanie mapy ich nie przelicza.&lt;/p&gt;&lt;h4&gt;Przykład&lt;/h4&gt;&lt;p&gt;&lt;code&gt;incircu_centerline($geometry)&lt;/code&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../algorithms/expressions.py" line="319"/>
        <source>&lt;h3&gt;incircu_label_line(geometry, trim, clearance, bend, min_elongation, smoothing, end_rule, points)&lt;/h3&gt;&lt;p&gt;The line a curved label of a lake or a wide river follows, as the &apos;Label lines of polygons&apos; algorithm computes it for the polygon&apos;s largest part: the main stem trimmed to where the polygon is at least &lt;i&gt;trim&lt;/i&gt; of its widest width, smoothed, at least &lt;i&gt;clearance&lt;/i&gt; local widths off the shore, bending no tighter than &lt;i&gt;bend&lt;/i&gt; local widths, reading from left to right. A compact part gives a label point (the centre of its largest incircle), or NULL when &lt;i&gt;points&lt;/i&gt; is false. Use it as the label&apos;s geometry generator with curved placement.&lt;/p&gt;&lt;h4&gt;Arguments&lt;/h4&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;geometry&lt;/b&gt;: a polygon, usually &lt;code&gt;$geometry&lt;/code&gt;.&lt;/li&gt;&lt;li&gt;&lt;b&gt;trim&lt;/b&gt;, &lt;b&gt;clearance&lt;/b&gt;, &lt;b&gt;bend&lt;/b&gt;, &lt;b&gt;min_elongation&lt;/b&gt;, &lt;b&gt;smoothing&lt;/b&gt; (optional): as in the algorithm; NULL: its defaults (0.5, 0.25, 0.5, 3, 0.5).&lt;/li&gt;&lt;li&gt;&lt;b&gt;end_rule&lt;/b&gt; (optional): &apos;main_stem&apos; (default) or &apos;longest_path&apos;.&lt;/li&gt;&lt;li&gt;&lt;b&gt;points&lt;/b&gt; (optional): true (default) to return a label point for compact parts.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Results are cached per geometry: panning and zooming do not recompute them.&lt;/p&gt;&lt;h4&gt;Example&lt;/h4&gt;&lt;p&gt;&lt;code&gt;incircu_label_line($geometry, points:=false)&lt;/code&gt;&lt;/p&gt;</source>
        <translation>&lt;h3&gt;incircu_label_line(geometry, trim, clearance, bend, min_elongation, smoothing, end_rule, points)&lt;/h3&gt;&lt;p&gt;Linia, wzdłuż której biegnie wygięta etykieta jeziora lub szerokiej rzeki, tak jak wyznacza ją algorytm 'Linie etykiet poligonów' dla największej części poligonu: główny nurt przycięty do miejsc, w których poligon ma co najmniej &lt;i&gt;trim&lt;/i&gt; swojej największej szerokości, wygładzony, co najmniej &lt;i&gt;clearance&lt;/i&gt; lokalnych szerokości od brzegu, wygięty nie ciaśniej niż &lt;i&gt;bend&lt;/i&gt; lokalnych szerokości, czytany od lewej do prawej. Zwarta część daje punkt etykiety (środek największego koła wpisanego) albo NULL, gdy &lt;i&gt;points&lt;/i&gt; jest fałszem. Użyj jej jako generatora geometrii etykiety z rozmieszczeniem zakrzywionym.&lt;/p&gt;&lt;h4&gt;Argumenty&lt;/h4&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;geometry&lt;/b&gt;: poligon, zwykle &lt;code&gt;$geometry&lt;/code&gt;.&lt;/li&gt;&lt;li&gt;&lt;b&gt;trim&lt;/b&gt;, &lt;b&gt;clearance&lt;/b&gt;, &lt;b&gt;bend&lt;/b&gt;, &lt;b&gt;min_elongation&lt;/b&gt;, &lt;b&gt;smoothing&lt;/b&gt; (opcjonalne): jak w algorytmie; NULL: jego wartości domyślne (0.5, 0.25, 0.5, 3, 0.5).&lt;/li&gt;&lt;li&gt;&lt;b&gt;end_rule&lt;/b&gt; (opcjonalny): 'main_stem' (domyślnie) lub 'longest_path'.&lt;/li&gt;&lt;li&gt;&lt;b&gt;points&lt;/b&gt; (opcjonalny): prawda (domyślnie), by zwracać punkt etykiety dla zwartych części.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Wyniki są zapamiętywane dla każdej geometrii: przesuwanie i powiększanie mapy ich nie przelicza.&lt;/p&gt;&lt;h4&gt;Przykład&lt;/h4&gt;&lt;p&gt;&lt;code&gt;incircu_label_line($geometry, points:=false)&lt;/code&gt;&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>LabelLinesAlgorithm</name>
    <message>
        <location filename="../algorithms/label_lines.py" line="48"/>
        <source>Label lines of polygons</source>
        <translation>Linie etykiet poligonów</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="51"/>
        <source>The line a curved lake or river name follows, or a label point for a round lake.</source>
        <translation>Linia, wzdłuż której biegnie wygięta nazwa jeziora lub rzeki, albo punkt etykiety dla okrągłego jeziora.</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="54"/>
        <source>Label lines</source>
        <translation>Linie etykiet</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="57"/>
        <source>Line layer: one label line per elongated polygon part, reading from left to right, with the input attributes plus source_fid, part, length, width_min (the narrowest width along the line: the tallest lettering that fits; layer units, metres for a layer in degrees), elongation and kind (line).</source>
        <translation>Warstwa liniowa: jedna linia etykiety na każdą wydłużoną część poligonu, czytana od lewej do prawej, z atrybutami wejściowymi oraz source_fid, part, length, width_min (najmniejsza szerokość wzdłuż linii: najwyższe mieszczące się litery; w jednostkach warstwy, w metrach dla warstwy w stopniach), elongation i kind (line).</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="65"/>
        <source>label,labels,lake,reservoir,river,name,curved,centerline,placement,cartography</source>
        <translation>etykieta,etykiety,jezioro,zbiornik,rzeka,nazwa,wygięta,linia środkowa,rozmieszczenie,kartografia</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="68"/>
        <source>Computes, for each polygon part, the line a curved label should follow: the main stem (as &apos;Centerline of polygons&apos; finds it, between split points, along guide lines or between automatic ends), trimmed at both ends to where the polygon is at least &apos;Trim&apos; times its widest width, smoothed so that it bends no tighter than &apos;Bend&apos; times the local width, and checked to keep &apos;Clearance&apos; times the local width off the shore at every segment (where it cannot, the longest piece that can is kept). Lines read from left to right (west to east; south to north when vertical). A part whose main stem is shorter than &apos;Minimum elongation&apos; times its mean width gets a label point instead: the centre of its largest incircle. Geographic layers are computed in a local metric projection; lengths are then in metres.</source>
        <translation>Wyznacza dla każdej części poligonu linię, wzdłuż której powinna biec wygięta etykieta: główny nurt (tak jak znajduje go 'Linia środkowa poligonów': między punktami podziału, wzdłuż linii prowadzących lub między automatycznymi końcami), przycięty z obu stron do miejsc, w których poligon ma co najmniej 'Przycięcie' razy swoją największą szerokość, wygładzony tak, by nie wyginał się ciaśniej niż 'Zgięcie' razy lokalna szerokość, i sprawdzony, czy każdy odcinek leży co najmniej 'Odstęp' razy lokalna szerokość od brzegu (gdzie to niemożliwe, zostaje najdłuższy fragment, który to spełnia). Linie czyta się od lewej do prawej (z zachodu na wschód; z południa na północ, gdy są pionowe). Część, której główny nurt jest krótszy niż 'Najmniejsze wydłużenie' razy jej średnia szerokość, dostaje zamiast tego punkt etykiety: środek największego koła wpisanego. Warstwy geograficzne są liczone w lokalnym odwzorowaniu metrycznym; długości są wtedy w metrach.</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="83"/>
        <source>Trim: ends where the width falls below this share of the widest</source>
        <translation>Przycięcie: końce tam, gdzie szerokość spada poniżej tego ułamka największej</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="83"/>
        <source>Both ends of the main stem are cut back to the first and last point where the polygon is at least this share of its widest width: out of the narrow tips and bays. 0 keeps the whole main stem.</source>
        <translation>Oba końce głównego nurtu są skracane do pierwszego i ostatniego punktu, w którym poligon ma co najmniej ten ułamek swojej największej szerokości: poza wąskie końce i zatoki. 0 zachowuje cały główny nurt.</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="83"/>
        <source>Clearance from the shore, share of the local width</source>
        <translation>Odstęp od brzegu, ułamek lokalnej szerokości</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="83"/>
        <source>Every segment of a label line is at least this share of the local width away from the outline (0.25: the line keeps to the middle half).</source>
        <translation>Każdy odcinek linii etykiety leży co najmniej o ten ułamek lokalnej szerokości od obrysu (0,25: linia trzyma się środkowej połowy).</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="83"/>
        <source>Tightest bend: radius of curvature, share of the local width</source>
        <translation>Najciaśniejsze zgięcie: promień krzywizny, ułamek lokalnej szerokości</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="83"/>
        <source>The radius of curvature at every vertex is at least this share of the local width: a label bends gently where the lake is wide.</source>
        <translation>Promień krzywizny w każdym wierzchołku wynosi co najmniej ten ułamek lokalnej szerokości: etykieta wygina się łagodnie tam, gdzie jezioro jest szerokie.</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="83"/>
        <source>Minimum elongation for a line</source>
        <translation>Najmniejsze wydłużenie dla linii</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="83"/>
        <source>A part whose main-stem length over mean width (its area over that length) is below this gets a label point, the centre of its largest incircle (a disc: 1.27; a 3:1 ellipse: 3.8).</source>
        <translation>Część, której stosunek długości głównego nurtu do średniej szerokości (pola powierzchni przez tę długość) jest mniejszy, dostaje punkt etykiety, środek największego koła wpisanego (koło: 1,27; elipsa 3:1: 3,8).</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="83"/>
        <source>Smoothing, share of the local width</source>
        <translation>Wygładzanie, ułamek lokalnej szerokości</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="83"/>
        <source>Standard deviation of the Gaussian smoothing along the main stem, as a share of the local width; it is lowered where the line would come too near the shore and raised where it would bend too tightly.</source>
        <translation>Odchylenie standardowe wygładzania gaussowskiego wzdłuż głównego nurtu jako ułamek lokalnej szerokości; jest zmniejszane tam, gdzie linia zbliżyłaby się za bardzo do brzegu, i zwiększane tam, gdzie wygięłaby się zbyt ciasno.</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="150"/>
        <source>Label points</source>
        <translation>Punkty etykiet</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="150"/>
        <source>Point layer: one label point per compact polygon part (the centre of its largest incircle), with the same fields (length 0, width_min the incircle&apos;s diameter, kind point).</source>
        <translation>Warstwa punktowa: jeden punkt etykiety na każdą zwartą część poligonu (środek jej największego koła wpisanego), z tymi samymi polami (length 0, width_min średnica koła, kind point).</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="159"/>
        <source>Number of labels</source>
        <translation>Liczba etykiet</translation>
    </message>
    <message>
        <location filename="../algorithms/label_lines.py" line="159"/>
        <source>Number of label lines and points written.</source>
        <translation>Liczba zapisanych linii i punktów etykiet.</translation>
    </message>
</context>
<context>
    <name>LinesCenterlineAlgorithm</name>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="51"/>
        <source>centerline,centreline,medial axis,banks,river,road,width,incircle</source>
        <translation>linia środkowa,oś,oś medialna,brzegi,rzeka,droga,szerokość,okrąg wpisany</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="65"/>
        <source>First lines (bank A)</source>
        <translation>Pierwsze linie (brzeg A)</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="72"/>
        <source>Second lines (bank B)</source>
        <translation>Drugie linie (brzeg B)</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="76"/>
        <source>Pairing field of the first lines</source>
        <translation>Pole parujące pierwszych linii</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="88"/>
        <source>Pairing field of the second lines</source>
        <translation>Pole parujące drugich linii</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="124"/>
        <source>{} holds no line.</source>
        <translation>{} nie zawiera żadnej linii.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="33"/>
        <source>Centerline between two lines</source>
        <translation>Linia środkowa między dwiema liniami</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="36"/>
        <source>One unbranched centerline between two lines, such as the two banks of a river.</source>
        <translation>Jedna nierozgałęziona linia środkowa między dwiema liniami, na przykład brzegami rzeki.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="39"/>
        <source>Centerline between lines</source>
        <translation>Linia środkowa między liniami</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="54"/>
        <source>Computes one unbranched centerline between two lines (for example the two banks of a river) with the Curve of Incircles: every vertex is the centre of a circle touching both lines. Lines are paired by equal values of the two pairing fields; without them each layer holds one line (its features and parts are merged). The lines must not cross. The M value of each vertex is the local width. The second lines are reprojected to the CRS of the first; geographic layers are computed in a local metric projection and distances are then in metres.</source>
        <translation>Wyznacza jedną nierozgałęzioną linię środkową między dwiema liniami (na przykład brzegami rzeki) metodą Krzywej Okręgów Wpisanych: każdy wierzchołek jest środkiem okręgu stycznego do obu linii. Linie łączone są w pary według równych wartości obu pól parujących; bez nich każda warstwa zawiera jedną linię (jej obiekty i części są scalane). Linie nie mogą się przecinać. Wartość M każdego wierzchołka to lokalna szerokość. Drugie linie są przeliczane do układu pierwszych; warstwy geograficzne są liczone w lokalnym odwzorowaniu metrycznym, a odległości są wtedy w metrach.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="72"/>
        <source>Line layer of the other side; reprojected to the CRS of the first lines when needed.</source>
        <translation>Warstwa liniowa drugiej strony; w razie potrzeby przeliczana do układu pierwszych linii.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="76"/>
        <source>Optional; a line of the first lines is paired with the line of the second lines that has the same value in &apos;Pairing field of the second lines&apos;.</source>
        <translation>Opcjonalne; linia z pierwszych linii łączona jest w parę z linią z drugich linii o tej samej wartości w 'Pole parujące drugich linii'.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="88"/>
        <source>Optional; required together with &apos;Pairing field of the first lines&apos;.</source>
        <translation>Opcjonalne; wymagane razem z 'Pole parujące pierwszych linii'.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="42"/>
        <source>Line layer, one line per pair of lines: the attributes of the first lines plus source_fid (the id of the pair&apos;s first feature in the first lines), length, width_min, width_mean, width_max (incircle diameters over the vertices with a positive width; layer units, metres for a layer in degrees) and n_vertices. Its ends_found (always false) and ends_from (always empty) are there only so that it has the fields of &apos;Centerline of polygons&apos;.</source>
        <translation>Warstwa liniowa, jedna linia na parę linii: atrybuty pierwszych linii oraz source_fid (identyfikator pierwszego obiektu pary w pierwszych liniach), length, width_min, width_mean, width_max (średnice okręgów wpisanych w wierzchołkach o dodatniej szerokości; jednostki warstwy, metry dla warstwy w stopniach) i n_vertices. Pola ends_found (zawsze fałsz) i ends_from (zawsze puste) istnieją tylko po to, by warstwa miała pola algorytmu 'Linia środkowa poligonów'.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="65"/>
        <source>Line layer of one side; the output has its CRS and its attributes. Z values (of both layers) are ignored: the centerline is computed in the plane.</source>
        <translation>Warstwa liniowa jednej strony; wynik ma jej układ współrzędnych i atrybuty. Wartości Z (obu warstw) są pomijane: linia środkowa jest obliczana na płaszczyźnie.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="109"/>
        <source>Give both {} and {}, or neither (then each layer holds one line).</source>
        <translation>Podaj oba pola, {} i {}, albo żadnego (wtedy każda warstwa zawiera jedną linię).</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="127"/>
        <source>{} holds {} separate lines that do not join into one; give {} and {} to pair them, or merge them into one line.</source>
        <translation>{} zawiera linie, które nie łączą się w jedną (jest ich {}); podaj {} i {}, aby je sparować, albo scal je w jedną linię.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="146"/>
        <source>No line in {} has {} = {!r}; line {} of {} unused.</source>
        <translation>Żadna linia w {} nie ma {} = {!r}; linia {} z {} nie została użyta.</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="156"/>
        <source>no line in {} has {} = {!r}</source>
        <translation>żadna linia w {} nie ma {} = {!r}</translation>
    </message>
    <message>
        <location filename="../algorithms/lines_centerline.py" line="174"/>
        <source>the lines of {} with this pairing value do not join into one</source>
        <translation>linie z {} o tej wartości parowania nie łączą się w jedną</translation>
    </message>
</context>
<context>
    <name>PolygonCenterlineAlgorithm</name>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="56"/>
        <source>centerline,centreline,medial axis,skeleton,river,road,dike,width,incircle</source>
        <translation>linia środkowa,oś,oś medialna,szkielet,rzeka,droga,wał,szerokość,okrąg wpisany</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="83"/>
        <source>Polygon layer</source>
        <translation>Warstwa poligonowa</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="92"/>
        <source>Split points</source>
        <translation>Punkty podziału</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="72"/>
        <source>One feature per polygon part</source>
        <translation>Jeden obiekt na każdą część poligonu</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="72"/>
        <source>Write one line feature per part of a multipart polygon instead of one MultiLineString per input feature.</source>
        <translation>Zapisz osobny obiekt liniowy dla każdej części poligonu wieloczęściowego zamiast jednego MultiLineString na obiekt wejściowy.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="39"/>
        <source>Centerline of polygons</source>
        <translation>Linia środkowa poligonów</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="42"/>
        <source>One unbranched centerline through each elongated polygon (river, road, dike).</source>
        <translation>Jedna nierozgałęziona linia środkowa każdego wydłużonego poligonu (rzeki, drogi, wału).</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="45"/>
        <source>Centerlines of polygons</source>
        <translation>Linie środkowe poligonów</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="59"/>
        <source>Computes one unbranched, loop-free centerline for each polygon (each part of a multipart polygon) with the Curve of Incircles: every vertex is the centre of a circle touching both sides of the outline. The line runs between the two &apos;Split points&apos; lying on the polygon&apos;s outline, or, without them, between automatic ends: those of the internal path along the &apos;Guide lines&apos;, else of the main stem (or the longest internal path, see &apos;Automatic ends&apos;). Islands (holes) are passed on the side of the wider channel, or ignored. The M value of each vertex is the local width. Geographic layers are computed in a local metric projection; distances are then in metres. A polygon that cannot be processed is skipped with a warning naming its id and the reason.</source>
        <translation>Wyznacza jedną nierozgałęzioną linię środkową bez pętli dla każdego poligonu (każdej części poligonu wieloczęściowego) metodą Krzywej Okręgów Wpisanych: każdy wierzchołek jest środkiem okręgu stycznego do obu stron obrysu. Linia biegnie między dwoma 'Punktami podziału' leżącymi na obrysie poligonu, a bez nich między końcami automatycznymi: końcami drogi wewnątrz kształtu wzdłuż 'Linii prowadzących', a bez nich głównego nurtu (lub najdłuższej drogi wewnątrz kształtu, zob. 'Końce automatyczne'). Wyspy (otwory) są omijane od strony szerszego koryta albo pomijane. Wartość M każdego wierzchołka to lokalna szerokość. Warstwy geograficzne są liczone w lokalnym odwzorowaniu metrycznym; odległości są wtedy w metrach. Poligon, którego nie da się przetworzyć, jest pomijany z ostrzeżeniem podającym jego identyfikator i przyczynę.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="92"/>
        <source>Points marking where each centerline starts and ends: two per polygon part, within &apos;Split point snapping tolerance&apos; of its exterior ring. A part with none gets automatic ends; a part with one or more than two is skipped. Another CRS is reprojected to the polygon layer&apos;s.</source>
        <translation>Punkty wyznaczające początek i koniec każdej linii środkowej: dwa na część poligonu, w odległości do 'Tolerancja przyciągania punktów podziału' od jej zewnętrznego obrysu. Część bez punktów dostaje automatycznie wyznaczone końce; część z jednym lub więcej niż dwoma punktami jest pomijana. Inny układ współrzędnych jest przeliczany do układu warstwy poligonowej.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="115"/>
        <source>Automatic ends</source>
        <translation>Końce automatyczne</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="114"/>
        <source>Main stem (widest path)</source>
        <translation>Główny nurt (najszersza droga)</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="114"/>
        <source>Longest path</source>
        <translation>Najdłuższa droga</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="125"/>
        <source>Guide lines</source>
        <translation>Linie prowadzące</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="125"/>
        <source>Rough river lines (a national network, OpenStreetMap waterways) for polygons without split points: the ends are those of the internal path that best covers the guide lines near the polygon. Gaps, offsets, generalised pieces and tributaries are fine. Another CRS is reprojected.</source>
        <translation>Przybliżone linie rzek (sieć krajowa, cieki OpenStreetMap) dla poligonów bez punktów podziału: końcami są końce drogi wewnątrz kształtu, która najlepiej pokrywa linie prowadzące w pobliżu poligonu. Przerwy, przesunięcia, uogólnione fragmenty i dopływy nie przeszkadzają. Inny układ współrzędnych jest przeliczany.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="48"/>
        <source>Line layer: input attributes plus source_fid (the polygon&apos;s feature id, to join the line back to it), length, width_min, width_mean, width_max (incircle diameters over the vertices with a positive width; layer units, metres for a layer in degrees), n_vertices, ends_found (true when no split points were used) and ends_from (split_points, guide or automatic).</source>
        <translation>Warstwa liniowa: atrybuty wejściowe oraz source_fid (identyfikator obiektu poligonu, do połączenia z nim linii), length, width_min, width_mean, width_max (średnice okręgów wpisanych w wierzchołkach o dodatniej szerokości; jednostki warstwy, metry dla warstwy w stopniach), n_vertices, ends_found (prawda, gdy nie użyto punktów podziału) i ends_from (split_points, guide lub automatic).</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="83"/>
        <source>Elongated polygons (rivers, roads, dikes); multipart polygons get one centerline per part. Z values are ignored: the centerline is computed in the plane.</source>
        <translation>Wydłużone poligony (rzeki, drogi, wały); poligony wieloczęściowe dostają jedną linię środkową na część. Wartości Z są pomijane: linia środkowa jest obliczana na płaszczyźnie.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="107"/>
        <source>{pass_through}: the line never crosses an island and goes round it on the side of the wider channel. {ignore}: holes are filled before computing.</source>
        <translation>{pass_through}: linia nigdy nie przecina wyspy i omija ją od strony szerszego koryta. {ignore}: otwory są wypełniane przed obliczeniem.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="115"/>
        <source>For polygons without split points. {main_stem}: the internal path that sweeps the largest channel area (length times width), so a wide main river wins over a longer but narrow side arm. {longest_path}: the tips of the two longest arms.</source>
        <translation>Dla poligonów bez punktów podziału. {main_stem}: droga wewnątrz kształtu obejmująca największą powierzchnię koryta (długość razy szerokość), więc szeroka rzeka główna wygrywa z dłuższą, lecz wąską odnogą. {longest_path}: końce dwóch najdłuższych ramion.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="260"/>
        <source>0: a millionth of the polygon&apos;s size</source>
        <translation>0: jedna milionowa rozmiaru poligonu</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="239"/>
        <source>{} Its ends were found automatically.</source>
        <translation>{} Jego końce wyznaczono automatycznie.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="262"/>
        <source>{} holds no point.</source>
        <translation>{} nie zawiera żadnego punktu.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_centerline.py" line="263"/>
        <source>no split point lies within {} of its outline, the {}; the nearest is {:.6g} {} away.</source>
        <translation>żaden punkt podziału nie leży w odległości {} od jego obrysu, czyli w granicach {}; najbliższy jest w odległości {:.6g} {}.</translation>
    </message>
</context>
<context>
    <name>PolygonNetworkAlgorithm</name>
    <message>
        <location filename="../algorithms/polygon_network.py" line="32"/>
        <source>Centerline network of polygons</source>
        <translation>Sieć linii środkowych poligonów</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="35"/>
        <source>The medial-axis tree between the arm ends of a confluence, a delta or a road junction.</source>
        <translation>Drzewo osi środkowej między końcami ramion zlewiska, delty lub skrzyżowania dróg.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="39"/>
        <source>Network branches</source>
        <translation>Gałęzie sieci</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="42"/>
        <source>network,confluence,delta,junction,crossing,medial axis,skeleton,river,road,width</source>
        <translation>sieć,zlewisko,delta,węzeł,skrzyżowanie,oś środkowa,szkielet,rzeka,droga,szerokość</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="45"/>
        <source>Computes, for each polygon (each part of a multipart polygon) with two or more &apos;Split points&apos; on its outline (the ends of the arms of a confluence, a delta or a road junction), the part of the medial axis that separates the outline&apos;s chains between consecutive split points: a tree with one end at each split point and junctions where a circle touches three chains, without side branches. Each branch is one line feature with the ids of the split points at its ends (&apos;junction&apos; at a junction), the chains on its right and left, its length and widths; the M value of each vertex is the local width. Two split points give exactly the polygon centerline. Islands (holes) are passed on the side of the wider channel, or ignored. Geographic layers are computed in a local metric projection; distances are then in metres. A polygon that cannot be processed is skipped with a warning naming its id and the reason.</source>
        <translation>Oblicza, dla każdego poligonu (każdej części poligonu wieloczęściowego) z dwoma lub więcej 'Punktami podziału' na obrysie (końcami ramion zlewiska, delty lub skrzyżowania dróg), część osi środkowej oddzielającą łańcuchy obrysu między kolejnymi punktami podziału: drzewo z jednym końcem w każdym punkcie podziału i węzłami tam, gdzie okrąg dotyka trzech łańcuchów, bez gałęzi bocznych. Każda gałąź to jeden obiekt liniowy z identyfikatorami punktów podziału na końcach ('junction' w węźle), łańcuchami po prawej i lewej stronie, długością i szerokościami; wartość M każdego wierzchołka to lokalna szerokość. Dwa punkty podziału dają dokładnie linię środkową poligonu. Wyspy (otwory) są omijane od strony szerszego koryta lub pomijane. Warstwy geograficzne są liczone w lokalnym odwzorowaniu metrycznym; odległości są wtedy w metrach. Poligon, którego nie można przetworzyć, jest pomijany z ostrzeżeniem podającym jego identyfikator i przyczynę.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="58"/>
        <source>Polygon layer</source>
        <translation>Warstwa poligonowa</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="67"/>
        <source>Split points</source>
        <translation>Punkty podziału</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="67"/>
        <source>The ends of the network: at least two per polygon part, within &apos;Split point snapping tolerance&apos; of its exterior ring, typically one across each arm&apos;s end. A part with fewer is skipped. Another CRS is reprojected to the polygon layer&apos;s.</source>
        <translation>Końce sieci: co najmniej dwa na część poligonu, w granicach 'Tolerancji przyciągania punktów podziału' od jego pierścienia zewnętrznego, zwykle jeden w poprzek końca każdego ramienia. Część z mniejszą liczbą jest pomijana. Inny układ współrzędnych jest przeliczany do układu warstwy poligonowej.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="77"/>
        <source>Split point id field</source>
        <translation>Pole identyfikatora punktu podziału</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="77"/>
        <source>Attribute naming each split point in from_point, to_point and the chains; default: its feature id.</source>
        <translation>Atrybut nazywający każdy punkt podziału w from_point, to_point i łańcuchach; domyślnie: identyfikator obiektu.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="111"/>
        <source>Number of branches</source>
        <translation>Liczba gałęzi</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="111"/>
        <source>Number of branch features written.</source>
        <translation>Liczba zapisanych obiektów gałęzi.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="58"/>
        <source>Polygons with several arms (confluences, deltas, road junctions); each part gets its network. Z values are ignored: the network is computed in the plane.</source>
        <translation>Poligony z kilkoma ramionami (zlewiska, delty, skrzyżowania dróg); każda część dostaje swoją sieć. Wartości Z są pomijane: sieć jest obliczana na płaszczyźnie.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="90"/>
        <source>{pass_through}: no branch crosses an island; each island belongs to the chain it is nearer to, so the branches go round it on the side of the wider channel. {ignore}: holes are filled before computing.</source>
        <translation>{pass_through}: żadna gałąź nie przecina wyspy; każda wyspa należy do bliższego łańcucha, więc gałęzie omijają ją od strony szerszego koryta. {ignore}: otwory są wypełniane przed obliczeniem.</translation>
    </message>
    <message>
        <location filename="../algorithms/polygon_network.py" line="99"/>
        <source>Line layer, one feature per branch: input attributes plus source_fid (the polygon&apos;s feature id, to join the branch back to it), from_point, to_point (split point ids or &apos;junction&apos;), right_chain, left_chain (each chain named &apos;a-b&apos; after the split points at its ends, counter-clockwise), length, width_min, width_mean, width_max (incircle diameters over the vertices with a positive width; layer units, metres for a layer in degrees) and n_vertices.</source>
        <translation>Warstwa liniowa, jeden obiekt na gałąź: atrybuty wejściowe oraz source_fid (identyfikator obiektu poligonu, do połączenia z nim gałęzi), from_point, to_point (identyfikatory punktów podziału lub 'junction'), right_chain, left_chain (każdy łańcuch nazwany 'a-b' od punktów podziału na jego końcach, przeciwnie do ruchu wskazówek zegara), length, width_min, width_mean, width_max (średnice okręgów wpisanych w wierzchołkach o dodatniej szerokości; jednostki warstwy, metry dla warstwy w stopniach) i n_vertices.</translation>
    </message>
</context>
</TS>

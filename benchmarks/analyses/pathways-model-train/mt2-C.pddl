;; [VIZ] segment_cells['seg-goal'] = [(20,0), (19,0), (18,0), (17,0), (16,0), (15,0), (14,0), (13,0), (12,0), (11,0), (10,0), (9,0), (8,0), (7,0), (6,0), (5,0), (4,0), (3,0), (2,0), (1,0), (0,0), (0,1), (0,2), (0,3), (0,4), (0,5), (0,6), (0,7), (0,8), (0,9), (0,10), (0,11), (0,12), (0,13), (0,14), (0,15), (0,16), (0,17), (0,18), (0,19), (0,20), (0,21), (0,22), (0,23), (0,24), (0,25), (0,26), (0,27), (0,28), (0,29), (0,30), (0,31), (0,32), (0,33), (0,34), (0,35), (0,36), (0,37), (0,38), (0,39), (0,40), (0,41), (0,42), (0,43), (0,44), (0,45), (0,46), (0,47), (0,48), (0,49), (0,50), (0,51), (0,52), (0,53), (0,54), (0,55), (0,56), (0,57), (0,58), (0,59), (0,60), (0,61), (0,62), (0,63), (1,63), (2,63), (3,63), (4,63), (5,63), (6,63), (7,63), (8,63), (9,63), (10,63), (11,63), (12,63), (13,63), (14,63), (15,63), (16,63), (17,63), (18,63), (19,63), (20,63)]
;; [VIZ] segment_cells['seg-hor1'] = [(121,0), (120,0), (119,0), (118,0), (117,0), (116,0), (115,0), (114,0), (113,0), (112,0), (111,0), (110,0), (109,0), (108,0), (107,0), (106,0), (105,0), (104,0), (103,0), (102,0), (101,0), (100,0), (99,0), (98,0), (97,0), (96,0), (95,0), (94,0), (93,0), (92,0), (91,0), (90,0), (89,0), (88,0), (87,0), (86,0), (85,0), (84,0), (83,0), (82,0), (81,0), (80,0), (79,0), (78,0), (77,0), (76,0), (75,0), (74,0), (73,0), (72,0), (71,0), (70,0), (69,0), (68,0), (67,0), (66,0), (65,0), (64,0), (63,0), (62,0), (61,0), (60,0), (59,0), (58,0), (57,0), (56,0), (55,0), (54,0), (53,0), (52,0), (51,0), (50,0), (49,0), (48,0), (47,0), (46,0), (45,0), (44,0), (43,0), (42,0), (41,0), (40,0), (39,0), (38,0), (37,0), (36,0), (35,0), (34,0), (33,0), (32,0), (31,0), (30,0), (29,0), (28,0), (27,0), (26,0), (25,0), (24,0), (23,0), (22,0)]
;; [VIZ] segment_cells['seg-hor2'] = [(121,21), (120,21), (119,21), (118,21), (117,21), (116,21), (115,21), (114,21), (113,21), (112,21), (111,21), (110,21), (109,21), (108,21), (107,21), (106,21), (105,21), (104,21), (103,21), (102,21), (101,21), (100,21), (99,21), (98,21), (97,21), (96,21), (95,21), (94,21), (93,21), (92,21), (91,21), (90,21), (89,21), (88,21), (87,21), (86,21), (85,21), (84,21), (83,21), (82,21), (81,21), (80,21), (79,21), (78,21), (77,21), (76,21), (75,21), (74,21), (73,21), (72,21), (71,21), (70,21), (69,21), (68,21), (67,21), (66,21), (65,21), (64,21), (63,21), (62,21), (61,21), (60,21), (59,21), (58,21), (57,21), (56,21), (55,21), (54,21), (53,21), (52,21), (51,21), (50,21), (49,21), (48,21), (47,21), (46,21), (45,21), (44,21), (43,21), (42,21), (41,21), (40,21), (39,21), (38,21), (37,21), (36,21), (35,21), (34,21), (33,21), (32,21), (31,21), (30,21), (29,21), (28,21), (27,21), (26,21), (25,21), (24,21), (23,21), (22,21)]
;; [VIZ] segment_cells['seg-hor3'] = [(22,42), (23,42), (24,42), (25,42), (26,42), (27,42), (28,42), (29,42), (30,42), (31,42), (32,42), (33,42), (34,42), (35,42), (36,42), (37,42), (38,42), (39,42), (40,42), (41,42), (42,42), (43,42), (44,42), (45,42), (46,42), (47,42), (48,42), (49,42), (50,42), (51,42), (52,42), (53,42), (54,42), (55,42), (56,42), (57,42), (58,42), (59,42), (60,42), (61,42), (62,42), (63,42), (64,42), (65,42), (66,42), (67,42), (68,42), (69,42), (70,42), (71,42), (72,42), (73,42), (74,42), (75,42), (76,42), (77,42), (78,42), (79,42), (80,42), (81,42), (82,42), (83,42), (84,42), (85,42), (86,42), (87,42), (88,42), (89,42), (90,42), (91,42), (92,42), (93,42), (94,42), (95,42), (96,42), (97,42), (98,42), (99,42), (100,42), (101,42), (102,42), (103,42), (104,42), (105,42), (106,42), (107,42), (108,42), (109,42), (110,42), (111,42), (112,42), (113,42), (114,42), (115,42), (116,42), (117,42), (118,42), (119,42), (120,42), (121,42)]
;; [VIZ] segment_cells['seg-hor4'] = [(22,63), (23,63), (24,63), (25,63), (26,63), (27,63), (28,63), (29,63), (30,63), (31,63), (32,63), (33,63), (34,63), (35,63), (36,63), (37,63), (38,63), (39,63), (40,63), (41,63), (42,63), (43,63), (44,63), (45,63), (46,63), (47,63), (48,63), (49,63), (50,63), (51,63), (52,63), (53,63), (54,63), (55,63), (56,63), (57,63), (58,63), (59,63), (60,63), (61,63), (62,63), (63,63), (64,63), (65,63), (66,63), (67,63), (68,63), (69,63), (70,63), (71,63), (72,63), (73,63), (74,63), (75,63), (76,63), (77,63), (78,63), (79,63), (80,63), (81,63), (82,63), (83,63), (84,63), (85,63), (86,63), (87,63), (88,63), (89,63), (90,63), (91,63), (92,63), (93,63), (94,63), (95,63), (96,63), (97,63), (98,63), (99,63), (100,63), (101,63), (102,63), (103,63), (104,63), (105,63), (106,63), (107,63), (108,63), (109,63), (110,63), (111,63), (112,63), (113,63), (114,63), (115,63), (116,63), (117,63), (118,63), (119,63), (120,63), (121,63)]
;; [VIZ] segment_cells['seg-left1'] = [(21,1), (21,2), (21,3), (21,4), (21,5), (21,6), (21,7), (21,8), (21,9), (21,10), (21,11), (21,12), (21,13), (21,14), (21,15), (21,16), (21,17), (21,18), (21,19), (21,20)]
;; [VIZ] segment_cells['seg-left2'] = [(21,22), (21,23), (21,24), (21,25), (21,26), (21,27), (21,28), (21,29), (21,30), (21,31), (21,32), (21,33), (21,34), (21,35), (21,36), (21,37), (21,38), (21,39), (21,40), (21,41)]
;; [VIZ] segment_cells['seg-left3'] = [(21,43), (21,44), (21,45), (21,46), (21,47), (21,48), (21,49), (21,50), (21,51), (21,52), (21,53), (21,54), (21,55), (21,56), (21,57), (21,58), (21,59), (21,60), (21,61), (21,62)]
;; [VIZ] segment_cells['seg-right1'] = [(122,20), (122,19), (122,18), (122,17), (122,16), (122,15), (122,14), (122,13), (122,12), (122,11), (122,10), (122,9), (122,8), (122,7), (122,6), (122,5), (122,4), (122,3), (122,2), (122,1)]
;; [VIZ] segment_cells['seg-right2'] = [(122,41), (122,40), (122,39), (122,38), (122,37), (122,36), (122,35), (122,34), (122,33), (122,32), (122,31), (122,30), (122,29), (122,28), (122,27), (122,26), (122,25), (122,24), (122,23), (122,22)]
;; [VIZ] segment_cells['seg-right3'] = [(122,62), (122,61), (122,60), (122,59), (122,58), (122,57), (122,56), (122,55), (122,54), (122,53), (122,52), (122,51), (122,50), (122,49), (122,48), (122,47), (122,46), (122,45), (122,44), (122,43)]
;; [VIZ] switch['sw-left1'] = (21,0)
;; [VIZ] switch['sw-left2'] = (21,21)
;; [VIZ] switch['sw-left3'] = (21,42)
;; [VIZ] switch['sw-left4'] = (21,63)
;; [VIZ] switch['sw-right1'] = (122,0)
;; [VIZ] switch['sw-right2'] = (122,21)
;; [VIZ] switch['sw-right3'] = (122,42)
;; [VIZ] switch['sw-right4'] = (122,63)
;; [VIZ] switch_entrance['sw-left1'] = 'seg-hor1'
;; [VIZ] switch_entrance['sw-left2'] = 'seg-left1'
;; [VIZ] switch_entrance['sw-left3'] = 'seg-left2'
;; [VIZ] switch_entrance['sw-left4'] = 'seg-left3'
;; [VIZ] switch_entrance['sw-right1'] = 'seg-right1'
;; [VIZ] switch_entrance['sw-right2'] = 'seg-right2'
;; [VIZ] switch_entrance['sw-right3'] = 'seg-right3'
;; [VIZ] switch_entrance['sw-right4'] = 'seg-hor4'
;; [VIZ] switch_exit['sw-left1'] = 'seg-left1'
;; [VIZ] switch_exit['sw-left2'] = 'seg-left2'
;; [VIZ] switch_exit['sw-left3'] = 'seg-left3'
;; [VIZ] switch_exit['sw-left4'] = 'seg-hor4'
;; [VIZ] switch_exit['sw-right1'] = 'seg-hor1'
;; [VIZ] switch_exit['sw-right2'] = 'seg-right1'
;; [VIZ] switch_exit['sw-right3'] = 'seg-right2'
;; [VIZ] switch_exit['sw-right4'] = 'seg-right3'
;; [VIZ] train_length['train1'] = 77
;; [VIZ] train_length['train2'] = 30
;; [VIZ] train_position['train1'] = ('seg-hor1', 100)
;; [VIZ] train_position['train2'] = ('seg-hor2', 100)
(define (problem model-train-time-metric-2)
  (:domain model-train-time-metric)
  (:objects
    seg-goal - segment
    seg-hor1 - segment
    seg-hor2 - segment
    seg-hor3 - segment
    seg-hor4 - segment
    seg-left1 - segment
    seg-left2 - segment
    seg-left3 - segment
    seg-right1 - segment
    seg-right2 - segment
    seg-right3 - segment
    sw-left1 - switch
    sw-left2 - switch
    sw-left3 - switch
    sw-left4 - switch
    sw-right1 - switch
    sw-right2 - switch
    sw-right3 - switch
    sw-right4 - switch
    train1 - train
    train2 - train
  )
  (:init
    (= (SEGMENT-LENGTH seg-goal) 104)
    (= (SEGMENT-LENGTH seg-hor1) 100)
    (= (SEGMENT-LENGTH seg-hor2) 100)
    (= (SEGMENT-LENGTH seg-hor3) 100)
    (= (SEGMENT-LENGTH seg-hor4) 100)
    (= (SEGMENT-LENGTH seg-left1) 20)
    (= (SEGMENT-LENGTH seg-left2) 20)
    (= (SEGMENT-LENGTH seg-left3) 20)
    (= (SEGMENT-LENGTH seg-right1) 20)
    (= (SEGMENT-LENGTH seg-right2) 20)
    (= (SEGMENT-LENGTH seg-right3) 20)
    (= (TRAIN-LENGTH train1) 77)
    (= (TRAIN-LENGTH train2) 30)
    (= (head-segment-position train1) 100)
    (= (head-segment-position train2) 100)
    (= (tail-segment-position train1) 23)
    (= (tail-segment-position train2) 70)
    (SWITCH-HAS-ENTRANCE sw-left1 seg-hor1)
    (SWITCH-HAS-ENTRANCE sw-left2 seg-hor2)
    (SWITCH-HAS-ENTRANCE sw-left2 seg-left1)
    (SWITCH-HAS-ENTRANCE sw-left3 seg-left2)
    (SWITCH-HAS-ENTRANCE sw-left4 seg-goal)
    (SWITCH-HAS-ENTRANCE sw-left4 seg-left3)
    (SWITCH-HAS-ENTRANCE sw-right1 seg-right1)
    (SWITCH-HAS-ENTRANCE sw-right2 seg-right2)
    (SWITCH-HAS-ENTRANCE sw-right3 seg-hor3)
    (SWITCH-HAS-ENTRANCE sw-right3 seg-right3)
    (SWITCH-HAS-ENTRANCE sw-right4 seg-hor4)
    (SWITCH-HAS-EXIT sw-left1 seg-goal)
    (SWITCH-HAS-EXIT sw-left1 seg-left1)
    (SWITCH-HAS-EXIT sw-left2 seg-left2)
    (SWITCH-HAS-EXIT sw-left3 seg-hor3)
    (SWITCH-HAS-EXIT sw-left3 seg-left3)
    (SWITCH-HAS-EXIT sw-left4 seg-hor4)
    (SWITCH-HAS-EXIT sw-right1 seg-hor1)
    (SWITCH-HAS-EXIT sw-right2 seg-hor2)
    (SWITCH-HAS-EXIT sw-right2 seg-right1)
    (SWITCH-HAS-EXIT sw-right3 seg-right2)
    (SWITCH-HAS-EXIT sw-right4 seg-right3)
    (first-train-in-head-segment train1)
    (first-train-in-head-segment train2)
    (head-segment train1 seg-hor1)
    (head-segment train2 seg-hor2)
    (idle train1)
    (idle train2)
    (last-train-in-tail-segment train1)
    (last-train-in-tail-segment train2)
    (segment-empty seg-goal)
    (segment-empty seg-hor3)
    (segment-empty seg-hor4)
    (segment-empty seg-left1)
    (segment-empty seg-left2)
    (segment-empty seg-left3)
    (segment-empty seg-right1)
    (segment-empty seg-right2)
    (segment-empty seg-right3)
    (switch-available sw-left1)
    (switch-available sw-left2)
    (switch-available sw-left3)
    (switch-available sw-left4)
    (switch-available sw-right1)
    (switch-available sw-right2)
    (switch-available sw-right3)
    (switch-available sw-right4)
    (switch-entrance sw-left1 seg-hor1)
    (switch-entrance sw-left2 seg-left1)
    (switch-entrance sw-left3 seg-left2)
    (switch-entrance sw-left4 seg-left3)
    (switch-entrance sw-right1 seg-right1)
    (switch-entrance sw-right2 seg-right2)
    (switch-entrance sw-right3 seg-right3)
    (switch-entrance sw-right4 seg-hor4)
    (switch-exit sw-left1 seg-left1)
    (switch-exit sw-left2 seg-left2)
    (switch-exit sw-left3 seg-left3)
    (switch-exit sw-left4 seg-hor4)
    (switch-exit sw-right1 seg-hor1)
    (switch-exit sw-right2 seg-right1)
    (switch-exit sw-right3 seg-right2)
    (switch-exit sw-right4 seg-right3)
    (tail-segment train1 seg-hor1)
    (tail-segment train2 seg-hor2)
  )
  (:goal (and (visited-segment train1 seg-goal) (visited-segment train2 seg-goal)))
  (:metric minimize (total-time))
)
